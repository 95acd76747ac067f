// Whether the capacitive calibration's stated ± is honest: the simulator's
// weights protocol (devices/simulator/CapacitiveWeightsScenario: settling,
// 1 % creep, linear drift, a wandering baseline, white noise) recorded with
// its load column over 60 seeds and calibrated as `calibrate-capacitive`
// does (core::calibration::stepsFromLoads, calibrateCapacitive), with the
// simulator's baseline stability given as `--baseline-wander` gives it
// (its random walk is invisible under the noise of any window). The truth
// is the simulator's: the beam model's ΔC per newton times (1 + its creep
// fraction), the sensitivity once the silicone has crept to rest.
//
// The coverage is tested on the paper's protocol (weights stacked up, then taken off):
// its loading and unloading steps straddle the crept-to-rest line. Weights
// placed one at a time read the dwell's sensitivity, 0.5 % low, far beyond
// the ±: the result says so (LoadsOnlyPlacedReadLowAndSaySo).
#include "core/SampleBlock.h"
#include "core/calibration/CapacitiveSteps.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "support/Coverage.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace tactiscope;
using devices::simulator::CapacitiveWeightsParameters;
using devices::simulator::CapacitiveWeightsScenario;
using devices::simulator::WeightProtocol;

namespace {

core::calibration::CapacitiveRecording record(CapacitiveWeightsScenario& scenario)
{
    const double rate = scenario.sampleRate_hz();
    core::SampleBlock block(1, static_cast<std::size_t>(scenario.duration_s() * rate), 0.0, 1.0 / rate);
    scenario.generate(block);
    core::calibration::CapacitiveRecording r;
    for (std::size_t i = 0; i < block.sampleCount(); ++i) {
        r.t_s.push_back(block.timeAt_s(i));
        r.capacitance_f.push_back(block.value(0, i));
        r.load_n.push_back(scenario.loadAt_n(block.timeAt_s(i)));
    }
    return r;
}

}  // namespace

TEST(CapacitiveCoverage, TheSensitivitysUncertaintyCoversTheBeamsTrueSensitivity)
{
    tactiscope::testing::Coverage sensitivity;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        CapacitiveWeightsParameters p;
        p.protocol = WeightProtocol::Cumulative;
        p.seed = seed;
        CapacitiveWeightsScenario scenario(p);
        const double truth = scenario.beam().capacitancePerNewton_f_per_n() * (1.0 + p.creepFraction);
        auto steps =
            core::calibration::stepsFromLoads(record(scenario), core::calibration::capacitiveStabilityDefaults());
        steps.input.baselineWander_f_per_sqrt_s = p.wander_f_per_sqrt_s;  // (without it: 19 of 60 within 1u)
        const auto result = core::calibration::calibrateCapacitive(steps.input, "No. 1", "test");
        sensitivity.add(result.forceFit->slope - truth, result.forceFit->slopeStandardError);
    }
    std::printf("sensitivity: %s\n", sensitivity.summary().c_str());
    EXPECT_TRUE(sensitivity.isGaussian());
}

// Weights placed one at a time, each removed before the next (the
// simulator's individual protocol): every step is a loading one, the
// silicone's creep is never balanced, and the sensitivity reads below the
// crept-to-rest truth by more than its ±. The result says so; the paper's
// protocol, whose unloading balances the creep, does not.
TEST(CapacitiveCoverage, LoadsOnlyPlacedReadLowAndSaySo)
{
    for (const WeightProtocol protocol : {WeightProtocol::Individual, WeightProtocol::Cumulative}) {
        CapacitiveWeightsParameters p;
        p.protocol = protocol;
        p.seed = 5;
        CapacitiveWeightsScenario scenario(p);
        const double truth = scenario.beam().capacitancePerNewton_f_per_n() * (1.0 + p.creepFraction);
        const auto steps =
            core::calibration::stepsFromLoads(record(scenario), core::calibration::capacitiveStabilityDefaults());
        const auto result = core::calibration::calibrateCapacitive(steps.input, "No. 1", "test");
        if (protocol == WeightProtocol::Individual) {
            EXPECT_LT(result.forceFit->slope, truth - 2.0 * result.forceFit->slopeStandardError);
            EXPECT_GT(result.forceFit->slope, truth * 0.98);
            ASSERT_EQ(result.cautions.size(), 1u);
            EXPECT_NE(result.cautions.front().find("creep"), std::string::npos);
        } else {
            EXPECT_TRUE(result.cautions.empty());
        }
    }
}
