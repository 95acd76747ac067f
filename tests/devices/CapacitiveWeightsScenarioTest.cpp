// The capacitive-weights simulator, calibrated from its cumulative protocol
// and then read back on individually placed weights: every weight within 5 %.
#include "devices/simulator/CapacitiveWeightsScenario.h"

#include "core/SampleBlock.h"
#include "core/capacitive/CapacitiveReadout.h"
#include "core/compliance/RobustMean.h"

#include <gtest/gtest.h>

using namespace tactiscope;
using core::calibration::kMilligramForce_n;
using devices::simulator::CapacitiveWeightsParameters;
using devices::simulator::CapacitiveWeightsScenario;
using devices::simulator::WeightProtocol;

namespace {

struct Recording {
    std::vector<double> t, c;
};

Recording record(CapacitiveWeightsScenario& scenario)
{
    const double rate = scenario.sampleRate_hz();
    core::SampleBlock block(1, static_cast<std::size_t>(scenario.duration_s() * rate), 0.0, 1.0 / rate);
    scenario.generate(block);
    Recording r;
    for (std::size_t i = 0; i < block.sampleCount(); ++i) {
        r.t.push_back(block.timeAt_s(i));
        r.c.push_back(block.value(0, i));
    }
    return r;
}

// Mean of the last 2 s of [from, to), as a wizard takes a settled step.
double settledMean(const Recording& r, double from_s, double to_s)
{
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < r.t.size(); ++i) {
        if (r.t[i] >= to_s - 2.0 && r.t[i] < to_s && r.t[i] >= from_s) {
            sum += r.c[i];
            ++n;
        }
    }
    return sum / n;
}

core::calibration::CapacitiveCalibrationResult calibrate(std::uint64_t seed)
{
    CapacitiveWeightsParameters p;
    p.seed = seed;
    CapacitiveWeightsScenario scenario(p);
    const Recording r = record(scenario);
    const core::calibration::StabilitySettings stable{2.0, 0.005e-12, 0.02e-12};
    core::calibration::CapacitiveCalibrationInput in;
    in.baseline = *core::calibration::firstStableWindow(r.t, r.c, stable);
    const std::size_t endIndex =
        static_cast<std::size_t>((scenario.duration_s() - p.baseline_s + 1.0) * p.sampleRate_hz);
    in.finalBaseline = *core::calibration::firstStableWindow(r.t, r.c, stable, endIndex);
    for (const auto& step : scenario.schedule())
        in.steps.push_back(
            {step.force_n, std::nullopt, settledMean(r, step.start_s, step.end_s), step.end_s - 1.0, step.loading});
    return core::calibration::calibrateCapacitive(in, "No. 1", "test");
}

}  // namespace

TEST(CapacitiveWeightsScenario, CalibrationRecoversTheBeamsTrueConstants)
{
    const auto result = calibrate(3);
    const CapacitiveWeightsScenario truth;
    const double trueSlope = truth.beam().capacitancePerNewton_f_per_n();
    EXPECT_NEAR(result.c0_f, 51.44e-12, 0.01e-12);
    // The 1 % creep shows up as up to 1 % more sensitivity.
    EXPECT_NEAR(result.forceFit->slope, trueSlope, 0.02 * trueSlope);
    EXPECT_GE(result.forceFit->rSquared, 0.999);
    EXPECT_NEAR(result.drift_f_per_s, 0.5e-15, 0.3e-15);
    ASSERT_TRUE(result.hysteresis.has_value());
    EXPECT_LT(*result.hysteresis, 0.03);
    EXPECT_NEAR(result.baselineSigma_f, 4e-15, 1.5e-15);
}

TEST(CapacitiveWeightsScenario, PlacedWeightsReadBackWithinFivePercent)
{
    const auto calibration = calibrate(3);
    CapacitiveWeightsParameters p;
    p.protocol = WeightProtocol::Individual;
    p.weights_mgf = {10, 20, 50, 100, 150};
    p.seed = 4;
    CapacitiveWeightsScenario scenario(p);
    const Recording r = record(scenario);
    core::capacitive::CapacitiveReadout readout(
        core::capacitive::CapacitiveSensitivity::fromCalibration(calibration, scenario.beam()),
        {calibration.baselineSigma_f, 3.0, 2.0, 30.0});
    std::vector<double> force(r.t.size());
    for (std::size_t i = 0; i < r.t.size(); ++i) force[i] = readout.push(r.t[i], r.c[i]).force_n;
    for (const auto& step : scenario.schedule()) {
        if (step.force_n == 0.0) continue;
        std::vector<double> settled;
        for (std::size_t i = 0; i < r.t.size(); ++i) {
            if (r.t[i] >= step.end_s - 2.0 && r.t[i] < step.end_s) settled.push_back(force[i]);
        }
        const double read = core::compliance::robustMean(settled).mean;
        EXPECT_NEAR(read, step.force_n, 0.05 * step.force_n)
            << step.force_n / kMilligramForce_n << " mgf read as " << read / kMilligramForce_n << " mgf";
    }
}
