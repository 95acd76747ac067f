// The calibration rigs of the simulator: a load placed through the rig
// reaches the reading as the physics says, worked by hand from the paper's
// beam (seed 001) and the bridge equation, and the manual capacitive
// protocol follows the rig instead of a script.
#include "devices/simulator/GaugeCalibrationScenario.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/ScenarioCatalog.h"

#include "core/SampleBlock.h"
#include "core/calibration/CapacitiveCalibration.h"

#include <gtest/gtest.h>

#include <numeric>

using namespace tactiscope;
using devices::simulator::GaugeCalibrationParameters;
using devices::simulator::GaugeCalibrationScenario;

namespace {

// Mean of `seconds` of the scenario's only channel.
double meanOver(devices::simulator::SimulatedScenario& scenario, double seconds)
{
    const double rate = scenario.sampleRate_hz();
    core::SampleBlock block(1, static_cast<std::size_t>(seconds * rate), 0.0, 1.0 / rate);
    scenario.generate(block);
    const auto values = block.channel(0);
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

}  // namespace

TEST(GaugeCalibrationScenario, AHungMassReadsThroughTheTrueGaugeFactor)
{
    GaugeCalibrationScenario scenario;
    const auto rig = scenario.loadRig();
    ASSERT_TRUE(rig);
    EXPECT_NEAR(meanOver(scenario, 2.0), 120.0, 0.5);  // the bridge's zero offset

    // 100 g on the tip of the 50 × 10 × 3 mm Perspex beam (E = 3 GPa):
    // F = 0.980665 N; root strain 6FL/(Ewt²) = 6·0.980665·0.05/(3e9·0.01·9e-6)
    // = 1.089628e-3; half bridge V_r = GF·ε/2 = 2.14·1.089628e-3/2 = 1.165902e-3;
    // at the ADC 1.165902e-3 · 5 V · 200 = 1.165902 V; ±10 V in 16 bits is
    // 3276.8 counts/V, so 3820.43 counts above the zero.
    rig->place(0.1 * 9.80665);
    meanOver(scenario, 2.0);  // the beam swings to rest (τ = 0.15 s)
    EXPECT_NEAR(meanOver(scenario, 2.0), 120.0 + 3820.43, 0.5);
}

TEST(GaugeCalibrationScenario, RejectsNonPhysicalParameters)
{
    GaugeCalibrationParameters p;
    p.trueGaugeFactor = 0.0;
    EXPECT_THROW(GaugeCalibrationScenario{p}, std::invalid_argument);
    p = {};
    p.settleTime_s = 0.0;
    EXPECT_THROW(GaugeCalibrationScenario{p}, std::invalid_argument);
}

TEST(CapacitiveCalibrationRig, TheManualProtocolFollowsTheRig)
{
    auto scenario = devices::simulator::makeScenario("capacitive-calibration");
    auto* capacitive = dynamic_cast<devices::simulator::CapacitiveWeightsScenario*>(scenario.get());
    ASSERT_NE(capacitive, nullptr);
    EXPECT_TRUE(capacitive->schedule().empty());
    const auto rig = scenario->loadRig();
    ASSERT_TRUE(rig);
    const double c0 = capacitive->parameters().geometry.c0_f;
    EXPECT_NEAR(meanOver(*scenario, 5.0), c0, 0.02e-12);

    // 100 mgf through the beam model's sensitivity (1.78 pF), after the lag
    // and the 1 % creep (τ 0.4 s and 4 s) have run, on the baseline's drift
    // of 0.5 fF/s at the window's middle (27.5 s).
    const double force = 100 * core::calibration::kMilligramForce_n;
    rig->place(force);
    meanOver(*scenario, 20.0);
    const double expected = c0 + capacitive->beam().capacitancePerNewton_f_per_n() * force * 1.01 +
                            capacitive->parameters().drift_f_per_s * 27.5;
    EXPECT_NEAR(meanOver(*scenario, 5.0), expected, 5e-15);
    EXPECT_FALSE(devices::simulator::makeScenario("capacitive-weights")->loadRig());
}
