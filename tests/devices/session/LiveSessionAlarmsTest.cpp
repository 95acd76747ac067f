// What a recording says about its link before anything goes wrong in it: a
// rate that was estimated, not given (a text device sends no clock), is a
// note at the session's start (no alarm: nothing went wrong), so every
// time in the session is read with that in mind. The source is the simulator, saying its rate is estimated.
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <thread>
#include <unistd.h>

using namespace tactiscope;

namespace {

class EstimatedRateSource final : public devices::BlockSource {
public:
    EstimatedRateSource()
        : m_inner(devices::simulator::makeScenario("panel-scan"))
    {
    }
    std::string name() const override { return m_inner.name(); }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_inner.channels(); }
    double nominalSampleRate_hz() const override { return m_inner.nominalSampleRate_hz(); }
    devices::ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override
    {
        return m_inner.readBlock(out, timeout);
    }
    std::optional<std::string> rateNote() const override { return "the sample rate was estimated"; }

private:
    devices::simulator::SimulatorSource m_inner;
};

}  // namespace

TEST(LiveSessionAlarms, AnEstimatedRateIsSaidAtTheRecordingsStart)
{
    const auto store =
        std::filesystem::temp_directory_path() / ("tactiscope-alarms-" + std::to_string(::getpid()) + ".tactiscope");
    std::filesystem::remove(store);
    std::int64_t id = 0;
    {
        devices::session::LiveSessionOptions options;
        options.storePath = store.string();
        devices::session::LiveSession session(std::make_unique<EstimatedRateSource>(), options);
        ASSERT_FALSE(session.startRecording({}));
        session.start();
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        id = session.stopRecording()->session;
    }
    core::storage::SessionStore sessions(store.string(), core::storage::Database::Access::ReadOnly);
    auto events = sessions.events(id);
    EXPECT_TRUE(std::ranges::none_of(events, [](const auto& e) { return e.kind == core::EventKind::Alarm; }));
    std::erase_if(events, [](const auto& e) { return e.kind != core::EventKind::Marker; });
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].start_s, 0.0);
    EXPECT_EQ(events[0].note, "the sample rate was estimated");
    std::filesystem::remove(store);
}
