// A fourth mode added by this file alone, through the two registries a
// sensor type fills (docs/conventions.md, "A new mode"): its definition in
// core (registerMode) and its live unit in devices/session
// (registerLiveUnit). Nothing else is edited, and the live session serves
// it: built on a device whose channels play its roles, chosen by setMode,
// fed the stream on the acquisition thread, asked for its zero, and asked
// each poll for what completed; the list it keeps is reached through its
// unit (LiveSession::unitAs), started again at a record press, with no
// door of its own in LiveSession.h (issue 52).
#include "core/ModeCapability.h"
#include "core/SampleBlock.h"
#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "devices/session/modes/PanelScanUnit.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

using namespace tactiscope;
using devices::session::LiveModeUnit;
using devices::session::LiveSession;
using tactiscope::devices::session::PanelScanUnit;

namespace {

class NewModeLiveTest : public tactiscope::testing::TempDirectoryTest {
protected:
    devices::session::LiveSessionOptions storeOptions()
    {
        devices::session::LiveSessionOptions options;
        options.storePath = file("s.tactiscope");
        return options;
    }
};

constexpr auto kPeakMode = static_cast<core::Mode>(41);
constexpr std::array kRoles{core::ChannelRole::CantileverA};

// The largest |strain| cantilever A has seen: the processor of a minimal
// "peak strain" mode.
class PeakSink final : public core::BlockSink {
public:
    explicit PeakSink(std::size_t channel)
        : m_channel(channel)
    {
    }
    void consume(const core::SampleBlock& block) override
    {
        for (std::size_t s = 0; s < block.sampleCount(); ++s) {
            const double value = std::abs(block.value(m_channel, s));
            if (value > m_peak.load()) m_peak = value;
        }
        m_samples += block.sampleCount();
    }
    double peak() const { return m_peak; }
    std::size_t samples() const { return m_samples; }

private:
    std::size_t m_channel;
    std::atomic<double> m_peak{0.0};
    std::atomic<std::size_t> m_samples{0};
};

class PeakUnit final : public LiveModeUnit {
public:
    explicit PeakUnit(const devices::session::LiveUnitSetup& setup)
        : m_sink(std::make_shared<PeakSink>(core::modeChannels(kPeakMode, setup.channels)->front()))
    {
    }
    std::shared_ptr<core::BlockSink> sink() const override { return m_sink; }
    std::optional<std::string> tare() override { return "the peak starts again only with a new connection"; }
    // A list of its own: the peak at each poll, started again with the
    // session's lists (a record press). Reached through unitAs<PeakUnit>().
    void take(const devices::session::LiveTake&) override
    {
        ++takes;
        m_peaks.push_back(m_sink->peak());
    }
    void clearLists() override { m_peaks.clear(); }
    std::string storedText(const devices::session::RecordingSummary&) const override { return "nothing stored"; }
    const std::vector<double>& peaks() const { return m_peaks; }

    std::shared_ptr<PeakSink> m_sink;
    int takes = 0;

private:
    std::vector<double> m_peaks;
};

class Registered {
public:
    Registered()
    {
        static const core::ModeDefinition definition{.mode = kPeakMode,
                                                     .name = "peak-strain",
                                                     .title = "Peak strain",
                                                     .needs = "a strain cantilever",
                                                     .roles = kRoles};
        core::registerMode(definition);
        devices::session::registerLiveUnit(
            kPeakMode, [](const devices::session::LiveUnitSetup& setup) { return std::make_unique<PeakUnit>(setup); });
    }
    ~Registered()
    {
        devices::session::unregisterLiveUnit(kPeakMode);
        core::unregisterMode(kPeakMode);
    }
    Registered(const Registered&) = delete;
    Registered& operator=(const Registered&) = delete;
};

// The panel-scan simulator, ten times real time: cantilever A for the peak.
std::unique_ptr<devices::BlockSource> spedUpPanelProbe()
{
    devices::simulator::SimulatorOptions pace;
    pace.speed = 10.0;
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario("panel-scan"), pace);
}

}  // namespace

TEST_F(NewModeLiveTest, AModeRegisteredAloneRunsInTheLiveSession)
{
    const Registered registered;
    LiveSession session(spedUpPanelProbe(), storeOptions());
    EXPECT_EQ(session.mode(), core::Mode::PanelScan);  // the device's own
    ASSERT_NE(session.unit(kPeakMode), nullptr);       // built: cantilever A is there
    ASSERT_FALSE(session.setMode(kPeakMode));
    EXPECT_EQ(session.tare().value_or(""), "the peak starts again only with a new connection");
    session.start();
    const auto* unit = dynamic_cast<const PeakUnit*>(session.unit(kPeakMode));
    ASSERT_NE(unit, nullptr);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (unit->m_sink->samples() < 2000 && std::chrono::steady_clock::now() < deadline) {
        session.poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_GE(unit->m_sink->samples(), 2000u);
    EXPECT_GT(unit->m_sink->peak(), 1e-6);  // the dent's strain, well above the noise
    EXPECT_GT(unit->takes, 0);
    // The panel scan runs beside it, as every mode the channels feed.
    EXPECT_NE(session.unitAs<PanelScanUnit>(), nullptr);
}

TEST_F(NewModeLiveTest, AModesOwnListIsReachedThroughItsUnitAndStartsAgainWithARecording)
{
    const Registered registered;
    LiveSession session(spedUpPanelProbe(), storeOptions());
    ASSERT_FALSE(session.setMode(kPeakMode));
    session.start();
    const auto* unit = session.unitAs<PeakUnit>();
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit, session.unit(kPeakMode));
    for (int i = 0; i < 10 || unit->peaks().empty(); ++i) {
        session.poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(unit->peaks().empty());
    // A record press (in a mode the store knows: a test's mode has no word
    // in the store's CHECK list) starts every unit's lists again.
    ASSERT_FALSE(session.setMode(core::Mode::PanelScan));
    ASSERT_FALSE(session.startRecording({}));
    EXPECT_TRUE(unit->peaks().empty());
    session.poll();
    EXPECT_FALSE(unit->peaks().empty());
    EXPECT_TRUE(session.stopRecording());
}
