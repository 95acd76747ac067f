// The signal setup through the live session (issue 57): a recording keeps
// its filters and math channels, its samples stay as they came, the live
// filtered and math series are, from the recording's first sample, what
// re-analysis computes from the stored samples with the stored setup, bit
// for bit; and a limit on a math channel raises its alarm live and stores
// it. The source is the simulator's panel scan.
#include "core/signal/SignalChain.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <thread>
#include <unistd.h>

using namespace tactiscope;

namespace {

std::filesystem::path storePath(const char* name)
{
    auto path = std::filesystem::temp_directory_path() /
                (std::string("tactiscope-") + name + "-" + std::to_string(::getpid()) + ".tactiscope");
    std::filesystem::remove(path);
    return path;
}

core::signal::SignalSetup notchAndDifference()
{
    core::signal::SignalSetup setup;
    core::dsp::FilterSettings filter;
    filter.notch_hz = 50.0;
    filter.lowpass_hz = 100.0;
    setup.filters = {{"a", filter}, {"b", filter}};
    setup.math = {core::math::parseMathDefinition("diff[µε]=a - b")};
    return setup;
}

std::unique_ptr<devices::BlockSource> panelScan()
{
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario("panel-scan"));
}

}  // namespace

TEST(LiveSignal, ARecordingsLiveFilteredAndMathSeriesAreWhatReanalysisComputesFromItsStoredSamples)
{
    const auto store = storePath("live-signal");
    devices::session::LiveSessionOptions options;
    options.storePath = store.string();
    options.signal = notchAndDifference();
    devices::session::LiveSession session(panelScan(), options);
    session.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the filters run before the recording
    ASSERT_FALSE(session.startRecording({}));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);
    const auto chain = session.signalChain();
    ASSERT_TRUE(chain);
    core::LiveCursor cursor, rawCursor;
    core::LiveChunk live, raw;
    chain->output()->readNew(cursor, live);
    session.buffer()->readNew(rawCursor, raw);

    core::storage::SessionStore sessions(store.string(), core::storage::Database::Access::ReadOnly);
    const auto stored = sessions.session(summary->session);
    ASSERT_TRUE(stored);
    EXPECT_EQ(core::signal::signalSetupFromJson(stored->metadata.signalSetup).text(), notchAndDifference().text());
    const auto n = sessions.sampleCount(summary->session);
    ASSERT_GT(n, 100u);
    const auto channels = sessions.channels(summary->session);
    std::vector<std::vector<double>> samples;
    std::vector<core::ChannelDescriptor> descriptors;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        samples.push_back(sessions.readChannel(summary->session, c, 0, n));
        descriptors.push_back(channels[c].descriptor);
    }
    // Where the recording began in the stream: the raw samples, rounded as
    // stored, that are the stored ones (the samples are never changed).
    const auto rounded = [](double v) { return static_cast<double>(static_cast<float>(v)); };
    std::optional<std::size_t> first;
    for (std::size_t i = 0; i + n <= raw.sampleCount() && !first; ++i)
        if (std::equal(samples[0].begin(), samples[0].end(), raw.values[0].begin() + static_cast<std::ptrdiff_t>(i),
                       [&](double s, double r) { return s == rounded(r); }))
            first = i;
    ASSERT_TRUE(first) << "the stored samples are not the stream's";
    ASSERT_GT(*first, 0u);

    const auto again = core::signal::chainSeries(core::signal::signalSetupFromJson(stored->metadata.signalSetup),
                                                 descriptors, channels[0].sampleRate_hz, samples);
    const std::size_t offset = *first + static_cast<std::size_t>(raw.firstIndex - live.firstIndex);
    ASSERT_EQ(again.size(), live.values.size());
    for (std::size_t o = 0; o < again.size(); ++o)
        for (std::size_t i = 0; i < n; ++i) {
            const double x = live.values[o][offset + i], y = again[o][i];
            ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << chain->outputs()[o].name << " sample " << i;
        }
    std::filesystem::remove(store);
}

TEST(LiveSignal, ALimitOnAMathChannelRaisesItsAlarmLiveAndTheRecordingStoresIt)
{
    const auto store = storePath("math-limit");
    devices::session::LiveSessionOptions options;
    options.storePath = store.string();
    devices::session::LiveSession session(panelScan(), options);
    core::signal::SignalSetup setup;
    setup.math = {core::math::parseMathDefinition("spread[µε]=abs(a - b)")};
    ASSERT_FALSE(session.setSignal(setup));
    // Any difference at all is above −1 µε: raised at once.
    const auto limit = core::trigger::parseLimit("spread>warning:-1");
    ASSERT_TRUE(limit.limit) << limit.error;
    ASSERT_FALSE(session.setLimits({*limit.limit}));
    ASSERT_FALSE(session.startRecording({}));
    session.start();
    std::vector<devices::session::LimitAlarm> alarms;
    for (int i = 0; i < 50 && alarms.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        session.poll();
        alarms = session.takeAlarms();
    }
    ASSERT_FALSE(alarms.empty());
    EXPECT_EQ(alarms.front().limit.quantity, "spread");
    EXPECT_EQ(alarms.front().unit, "µε");
    EXPECT_EQ(session.setSignal({}), "a recording keeps its filters and math channels; stop it first");
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);
    core::storage::SessionStore sessions(store.string(), core::storage::Database::Access::ReadOnly);
    const auto events = sessions.events(summary->session);
    const auto alarm = std::ranges::find(events, core::EventKind::Alarm, &core::storage::SessionEvent::kind);
    ASSERT_NE(alarm, events.end());
    EXPECT_NE(alarm->note.find("spread above its warning limit -1 µε"), std::string::npos) << alarm->note;
    std::filesystem::remove(store);
}

TEST(LiveSignal, AMathChannelOnAChannelTheDeviceLacksIsRefusedAndTheSetupStays)
{
    devices::session::LiveSessionOptions options;
    options.storePath = storePath("math-refused").string();
    devices::session::LiveSession session(panelScan(), options);
    core::signal::SignalSetup setup;
    setup.math = {core::math::parseMathDefinition("f[mN]=force * 2")};
    const auto refusal = session.setSignal(setup);
    ASSERT_TRUE(refusal);
    EXPECT_NE(refusal->find("force"), std::string::npos) << *refusal;
    EXPECT_TRUE(session.signalSetup().empty());
    EXPECT_FALSE(session.signalChain());
}
