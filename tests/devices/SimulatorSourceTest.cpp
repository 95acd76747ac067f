// SimulatorSource: block framing, finite durations and real-time pacing.
#include "devices/simulator/SimulatorSource.h"

#include "core/SampleBlock.h"
#include "devices/simulator/ScenarioCatalog.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <tuple>

using namespace std::chrono_literals;
using tactiscope::core::SampleBlock;
using tactiscope::devices::ReadStatus;
using tactiscope::devices::simulator::makeScenario;
using tactiscope::devices::simulator::Pacing;
using tactiscope::devices::simulator::SimulatorOptions;
using tactiscope::devices::simulator::SimulatorSource;

TEST(SimulatorSource, NamesItselfAfterTheScenario)
{
    const SimulatorSource source(makeScenario("panel-scan"));
    EXPECT_EQ(source.name(), "Simulator — panel scan");
    EXPECT_EQ(source.nominalSampleRate_hz(), 500.0);
    EXPECT_EQ(source.channels().size(), 2u);
}

TEST(SimulatorSource, ProducesContiguousBlocksUntilTheDurationEnds)
{
    // 1.01 s at 500 Hz is 505 samples: 50 full blocks of 10 and one of 5.
    SimulatorSource source(makeScenario("panel-scan"), {Pacing::AsFastAsPossible, 10, 1.01});
    SampleBlock block;
    std::uint64_t samples = 0;
    std::uint32_t blocks = 0;
    while (source.readBlock(block, 0ms) == ReadStatus::Block) {
        EXPECT_EQ(block.firstSampleIndex(), samples);
        EXPECT_EQ(block.sequence(), blocks);
        EXPECT_DOUBLE_EQ(block.t0_s(), static_cast<double>(samples) * 0.002);
        EXPECT_DOUBLE_EQ(block.dt_s(), 0.002);
        EXPECT_EQ(block.channelCount(), 2u);
        samples += block.sampleCount();
        ++blocks;
    }
    EXPECT_EQ(samples, 505u);
    EXPECT_EQ(blocks, 51u);
    EXPECT_EQ(block.sampleCount(), 5u);
    EXPECT_EQ(source.readBlock(block, 0ms), ReadStatus::Finished);
}

// A slow device's samples come one at a time, not a second's worth in a
// block (fresh eyes, issue 52: the 10 Hz beam's readouts lagged its traces
// by up to a second); no block spans more than 20 ms or one sample.
TEST(SimulatorSource, ABlockSpansAtMostTwentyMillisecondsOrOneSample)
{
    for (const auto& [scenario, rate_hz, perBlock] :
         {std::tuple{"capacitive-overload", 10.0, 1u}, std::tuple{"panel-scan", 500.0, 10u}}) {
        SCOPED_TRACE(scenario);
        SimulatorSource source(makeScenario(scenario), {Pacing::AsFastAsPossible, 10, 2.0});
        ASSERT_EQ(source.nominalSampleRate_hz(), rate_hz);
        SampleBlock block;
        std::uint64_t samples = 0;
        while (source.readBlock(block, 0ms) == ReadStatus::Block) {
            EXPECT_EQ(block.sampleCount(), perBlock);
            samples += block.sampleCount();
        }
        EXPECT_EQ(samples, static_cast<std::uint64_t>(2.0 * rate_hz));
    }
}

TEST(SimulatorSource, RealTimePacingNeverDeliversABlockBeforeItsTime)
{
    SimulatorSource source(makeScenario("panel-scan"), {Pacing::RealTime, 10, std::nullopt});
    SampleBlock block;
    // The first block (20 ms of data) cannot be ready at once.
    EXPECT_EQ(source.readBlock(block, 0ms), ReadStatus::Timeout);

    const auto start = std::chrono::steady_clock::now();
    std::uint64_t samples = 0;
    while (samples < 100) {
        if (source.readBlock(block, 50ms) == ReadStatus::Block) samples += block.sampleCount();
    }
    // 100 samples at 500 Hz take 200 ms of simulated time; the clock
    // started at the first call, before `start`.
    EXPECT_GE(std::chrono::steady_clock::now() - start, 150ms);
}

TEST(SimulatorSource, AFasterSpeedStillPacesSimulatedTime)
{
    SimulatorOptions options;
    options.speed = 10.0;
    SimulatorSource source(makeScenario("panel-scan"), options);
    SampleBlock block;
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t samples = 0;
    while (samples < 1000) {
        if (source.readBlock(block, 50ms) == ReadStatus::Block) samples += block.sampleCount();
    }
    // 2 s of simulated time at ten times real time: 200 ms at the least.
    EXPECT_GE(std::chrono::steady_clock::now() - start, 150ms);
}

TEST(SimulatorSource, RejectsBadOptions)
{
    EXPECT_THROW(SimulatorSource(nullptr), std::invalid_argument);
    EXPECT_THROW(SimulatorSource(makeScenario("panel-scan"), {Pacing::RealTime, 0, std::nullopt}),
                 std::invalid_argument);
    EXPECT_THROW(SimulatorSource(makeScenario("panel-scan"), {Pacing::RealTime, 10, -1.0}), std::invalid_argument);
    EXPECT_THROW(SimulatorSource(makeScenario("panel-scan"), {Pacing::RealTime, 10, std::nullopt, 0.0}),
                 std::invalid_argument);
}

TEST(ScenarioCatalog, KnowsPanelScanAndRefusesUnknownIds)
{
    EXPECT_NE(makeScenario("panel-scan"), nullptr);
    EXPECT_EQ(makeScenario("no-such-scenario"), nullptr);
}
