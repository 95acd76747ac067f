// A filter set in review (core/signal/ReviewFilterLane): a lane over a real
// store whose windows, however placed, are the filter run over the whole
// session; zero-phase shows a pass-band line where it is, causal as late as
// its delay; the stored samples are not changed; and the session's lanes
// name it after its channel.
#include "core/signal/ReviewFilterLane.h"

#include "core/SampleBlock.h"
#include "core/derived/SessionLanes.h"
#include "core/dsp/ChannelFilter.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using ReviewFilterLaneTest = tactiscope::testing::TempDirectoryTest;

constexpr double kRate = 1000.0;
constexpr std::size_t kSamples = 20000;

// a [µε]: a 2 Hz line of 100 µε under 1,000 µε of 50 Hz hum and 0.1 µε of noise.
std::vector<double> hummed()
{
    std::mt19937 random(5);
    std::normal_distribution<double> noise(0.0, 0.1e-6);
    std::vector<double> a(kSamples);
    for (std::size_t i = 0; i < kSamples; ++i) {
        const double t = static_cast<double>(i) / kRate;
        a[i] = 100e-6 * std::sin(2.0 * std::numbers::pi * 2.0 * t) +
               1000e-6 * std::sin(2.0 * std::numbers::pi * 50.0 * t) + noise(random);
    }
    return a;
}

std::int64_t writeSession(SessionStore& store, const std::vector<double>& a)
{
    SessionMetadata metadata;
    metadata.mode = Mode::General;
    const std::vector<ChannelDescriptor> channels{{"a", "strain", ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, kRate);
    SampleBlock block(1, a.size(), 0.0, 1.0 / kRate, 0);
    std::ranges::copy(a, block.channel(0).begin());
    store.appendBlocks(id, std::vector{block});
    store.endSession(id, SessionStatus::Complete);
    return id;
}

// How far samples from `first` on stray from the 2 Hz line at its phase.
double farthestFromTheLine(const std::vector<double>& values, std::size_t first)
{
    double farthest = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double t = static_cast<double>(first + i) / kRate;
        farthest = std::max(farthest, std::fabs(values[i] - 100e-6 * std::sin(2.0 * std::numbers::pi * 2.0 * t)));
    }
    return farthest;
}

}  // namespace

TEST_F(ReviewFilterLaneTest, AnyWindowIsTheWholeRunsAndTheStoreIsUnchanged)
{
    SessionStore store(file("s.tactiscope"));
    const auto a = hummed();
    const auto id = writeSession(store, a);
    const auto before = store.readChannel(id, 0, 0, kSamples);
    for (const bool zeroPhase : {true, false}) {
        dsp::FilterSettings settings;
        settings.notch_hz = 50.0;
        settings.lowpass_hz = 20.0;
        settings.zeroPhase = zeroPhase;
        signal::ReviewFilterLane lane(store, id, 0, {"a", "strain", ChannelKind::Strain}, kRate, settings, "a.review");
        const auto whole = dsp::filterSeries(settings, kRate, before);
        for (const auto& [first, count] :
             {std::pair<std::uint64_t, std::uint64_t>{0, 500}, {7000, 1234}, {19000, 1000}}) {
            const auto window = lane.exact(first, count);
            ASSERT_EQ(window.size(), count);
            for (std::size_t i = 0; i < count; ++i)
                ASSERT_NEAR(window[i], whole[first + i], 1e-9 * 1000e-6) << first << "+" << i << " zero " << zeroPhase;
        }
        EXPECT_GT(lane.settling(), 0u);
    }
    EXPECT_EQ(store.readChannel(id, 0, 0, kSamples), before);  // bit for bit
}

TEST_F(ReviewFilterLaneTest, ZeroPhaseKeepsThePassBandsLineWhereItIsAndCausalLagsIt)
{
    SessionStore store(file("s.tactiscope"));
    const auto id = writeSession(store, hummed());
    dsp::FilterSettings settings;
    settings.notch_hz = 50.0;
    settings.lowpass_hz = 20.0;
    settings.zeroPhase = true;
    signal::ReviewFilterLane zero(store, id, 0, {"a", "strain", ChannelKind::Strain}, kRate, settings, "a.review");
    // The 2 Hz line alone is left, in phase: within 0.5 % of its amplitude
    // (the hum 60 dB down, the noise filtered).
    EXPECT_LT(farthestFromTheLine(zero.exact(5000, 10000), 5000), 0.005 * 100e-6);
    // Causal, it lags by its group delay at 2 Hz: the line is off by far more.
    settings.zeroPhase = false;
    signal::ReviewFilterLane causal(store, id, 0, {"a", "strain", ChannelKind::Strain}, kRate, settings, "a.r");
    const double off = farthestFromTheLine(causal.exact(5000, 10000), 5000);
    EXPECT_GT(off, 0.05 * 100e-6);
}

TEST_F(ReviewFilterLaneTest, TheSessionsLanesNameEachAfterItsChannelAndRefuseInWords)
{
    SessionStore store(file("s.tactiscope"));
    const auto id = writeSession(store, hummed());
    const auto session = *store.session(id);
    derived::LaneOptions options;
    dsp::FilterSettings lowpass;
    lowpass.lowpass_hz = 20.0;
    dsp::FilterSettings notch;
    notch.notch_hz = 50.0;
    options.reviewFilters = {{"a", lowpass}, {"a", notch}, {"missing", notch}};
    auto lanes = derived::sessionLanes(store, session, options);
    std::vector<std::string> names;
    for (const auto& lane : lanes.lanes) names.push_back(lane->descriptor().name);
    EXPECT_EQ(names, (std::vector<std::string>{"a", "a.review", "a.review2"}));
    EXPECT_EQ(lanes.lanes[1]->descriptor().unit, "strain");
    // A cut-off above Nyquist is refused, and the lanes say why.
    dsp::FilterSettings tooHigh;
    tooHigh.lowpass_hz = 600.0;
    options.reviewFilters = {{"a", tooHigh}};
    lanes = derived::sessionLanes(store, session, options);
    EXPECT_EQ(lanes.lanes.size(), 1u);
    EXPECT_NE(lanes.problem.find("a cannot be filtered so"), std::string::npos) << lanes.problem;
}
