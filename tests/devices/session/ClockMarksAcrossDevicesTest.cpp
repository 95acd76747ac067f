// The built-in simulator beside a TSP/1 probe in one session (issue 55):
// simulators at 10 and 1,000 Hz and an emulated load cell at 500 Hz behind
// a real pty, recorded through the one live pipeline, all marking one
// instant of the host's steady clock. The simulator times its samples by
// the host's clock itself (an exact mapping: sample k at its pace's start
// plus k + 1 periods); the probe's frames are mapped from their arrivals.
// Each mark, found in the stored samples alone on the session's axis, must
// lie within 0.5 ms of the others and within twice their stated relative
// uncertainty: a simulator whose samples were a period off its mapping
// would put the 10 Hz mark 100 ms late.
#include "core/storage/SessionStore.h"
#include "core/timing/ClockMappingJson.h"
#include "devices/PortSource.h"
#include "devices/SteadyClock.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/session/LivePipeline.h"
#include "devices/simulator/LoadCellScenario.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "devices/transport/PosixSerialTransport.h"

#include "support/ClockMarks.h"
#include "support/TempDirectory.h"
#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

using namespace tactiscope;

namespace {

using ClockMarksAcrossDevices = tactiscope::testing::TempDirectoryTest;

// The probe's mapping states its ± from 20 bins of a quarter second on
// (core/timing/ClockAlignment.h): the mark comes well after.
constexpr double kRecord_s = 7.0;
constexpr double kMarkAfter_s = 5.0;  // after the record press

std::unique_ptr<devices::BlockSource> simulatorAt(double rate_hz, double markAt_s, std::uint64_t seed)
{
    devices::simulator::SimulatorOptions options;
    options.markAt_s = markAt_s;
    return std::make_unique<devices::simulator::SimulatorSource>(
        devices::simulator::makeScenario(devices::simulator::kLoadCellScenario, seed, rate_hz), options);
}

}  // namespace

TEST_F(ClockMarksAcrossDevices, TheSimulatorAtTenAndAThousandHertzAndAProbeAtFiveHundredMarkOneInstant)
{
    const double markAt_s = devices::steadySeconds() + kMarkAfter_s + 1.0;
    const std::string link = tactiscope::testing::uniqueTempPath("clock-probe");
    devices::emulator::EmulatorOptions probe;
    probe.linkPath = link;
    probe.scenario = devices::simulator::kLoadCellScenario;
    probe.rate_hz = 500.0;
    probe.seed = 3;
    // 250 frames a second: the mapping states its ± from 400 frames on.
    probe.samplesPerFrame = 2;
    probe.markAt_s = markAt_s;
    devices::emulator::ProbeEmulator emulator(probe);
    emulator.start();

    devices::session::LivePipeline pipeline(file("s.tactiscope"));
    struct Device {
        std::string name;
        double rate_hz;
    };
    const std::array<Device, 3> devices{Device{"slow", 10.0}, Device{"fastest", 1000.0}, Device{"probe", 500.0}};
    ASSERT_FALSE(pipeline.add(simulatorAt(10.0, markAt_s, 1), {}, "slow"));
    ASSERT_FALSE(pipeline.add(simulatorAt(1000.0, markAt_s, 2), {}, "fastest"));
    ASSERT_FALSE(pipeline.add(
        std::make_unique<devices::PortSource>(std::make_unique<devices::transport::PosixSerialTransport>(link, 921600),
                                              devices::PortSourceOptions{}),
        {}, "probe"));
    pipeline.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    pipeline.poll();
    ASSERT_FALSE(pipeline.startRecording({}, kRecord_s));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!pipeline.recordingComplete() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        pipeline.poll();
    }
    ASSERT_TRUE(pipeline.recordingComplete());
    const auto end = pipeline.stopRecording();
    ASSERT_TRUE(end);
    emulator.stop();

    core::storage::SessionStore store(file("s.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto parts = store.parts(end->session);
    ASSERT_EQ(parts.size(), devices.size());
    std::array<core::timing::ClockMapping, 3> clocks;
    std::array<std::vector<double>, 3> times, values;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        ASSERT_EQ(parts[i].deviceName, devices[i].name);
        const auto clock = core::timing::clockMappingFromJson(parts[i].clockJson);
        ASSERT_TRUE(clock && clock->uncertainty_s(0.0)) << parts[i].clockJson;
        clocks[i] = *clock;
        const auto count = store.sampleCount(parts[i].id);
        values[i] = store.readChannel(parts[i].id, 0, 0, count);
        for (std::uint64_t k = 0; k < count; ++k)
            times[i].push_back(clock->host_s(static_cast<double>(k) / devices[i].rate_hz));
    }
    const auto rough = tactiscope::testing::roughMark_s(times[1], values[1]);
    ASSERT_TRUE(rough) << "the mark was not recorded";
    std::array<tactiscope::testing::FoundMark, 3> marks{};
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const auto found = tactiscope::testing::markTime_s(times[i], values[i], *rough,
                                                           devices::simulator::markHalfWidth_s(devices[i].rate_hz));
        ASSERT_TRUE(found) << devices[i].name;
        marks[i] = *found;
    }
    for (std::size_t i = 0; i < devices.size(); ++i)
        for (std::size_t j = i + 1; j < devices.size(); ++j) {
            const double apart = marks[i].t_s - marks[j].t_s;
            const auto clocksU = core::timing::relativeUncertainty_s(clocks[i], clocks[j], 0.0, kRecord_s);
            ASSERT_TRUE(clocksU);
            // The clocks' doubt and where each mark's noisy samples put it.
            const double u = std::hypot(*clocksU, marks[i].u_s, marks[j].u_s);
            std::printf("%s − %s: %+.1f µs (clocks ± %.3f ms, with the marks' noise ± %.3f ms)\n",
                        devices[i].name.c_str(), devices[j].name.c_str(), apart * 1e6, *clocksU * 1e3, u * 1e3);
            EXPECT_LE(std::abs(apart), 0.5e-3) << devices[i].name << " and " << devices[j].name;
            EXPECT_LE(std::abs(apart), 2.0 * u) << devices[i].name << " and " << devices[j].name;
        }
}
