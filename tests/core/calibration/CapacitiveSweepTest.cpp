// A reference-force sweep against known truth, written here sample by
// sample: a beam of known C0 and sensitivity, a load cell with a zero
// offset and noise. The calibration finds the reference's zero, C0 and the
// sensitivity within their stated ±; a beam lagging the sweep shows as
// hysteresis and in the ±, not as a biased slope; two cycles turn three
// times; a sweep that does not start unloaded, a reference that never
// moves and an unsettled start are refused.
#include "core/calibration/CapacitiveSweep.h"
#include "core/calibration/ReferencePairing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tactiscope::core::calibration;

namespace {

constexpr double kC0_f = 51.44e-12;
constexpr double kSensitivity_f_per_n = 1.2e-9;  // 1.2 pF/mN
constexpr double kPeak_n = 1.5e-3;
constexpr double kReferenceZero_n = 20e-6;

struct Sweep {
    double rate_hz = 10.0;
    double rest_s = 10.0;  // unloaded before and after
    double ramp_s = 20.0;  // each way
    int cycles = 1;
    double lag_s = 0.0;  // the beam's first-order lag behind the force
    double startLoad_n = 0.0;
    double referenceNoise_n = 0.3e-6;
    double capacitanceNoise_f = 4e-15;
};

double forceAt(const Sweep& s, double t)
{
    const double u = t - s.rest_s;
    const double cycle = 2.0 * s.ramp_s;
    if (u < 0.0 || u >= cycle * s.cycles) return s.startLoad_n;
    const double phase = std::fmod(u, cycle);
    return s.startLoad_n + kPeak_n * (phase < s.ramp_s ? phase / s.ramp_s : 2.0 - phase / s.ramp_s);
}

CapacitiveRecording record(const Sweep& s, unsigned seed = 1)
{
    std::mt19937_64 random(seed);
    std::normal_distribution<double> unit;
    CapacitiveRecording r;
    const double length = 2.0 * s.rest_s + 2.0 * s.ramp_s * s.cycles;
    const double dt = 1.0 / s.rate_hz;
    double felt = forceAt(s, 0.0);
    for (double t = 0.0; t < length; t += dt) {
        const double force = forceAt(s, t);
        if (s.lag_s > 0.0)
            felt += (force - felt) * (1.0 - std::exp(-dt / s.lag_s));
        else
            felt = force;
        r.t_s.push_back(t);
        r.capacitance_f.push_back(kC0_f + kSensitivity_f_per_n * felt + s.capacitanceNoise_f * unit(random));
        r.load_n.push_back(force + kReferenceZero_n + s.referenceNoise_n * unit(random));
    }
    return r;
}

SweepSettings settings()
{
    return {.stability = capacitiveStabilityDefaults()};
}

}  // namespace

TEST(CapacitiveSweepTest, FindsTheZeroC0AndTheSensitivityOfAKnownBeam)
{
    const SweepSteps sweep = stepsFromSweep(record({}), settings());
    EXPECT_NEAR(sweep.referenceZero_n, kReferenceZero_n, 0.2e-6);
    EXPECT_NEAR(sweep.span_n, kPeak_n, 2e-6);
    EXPECT_EQ(sweep.turns, 1u);
    ASSERT_EQ(sweep.steps.steps.size(), 20u);  // ten bins each way
    const auto result = calibrateCapacitive(sweep.steps.input, "beam", "");
    ASSERT_TRUE(result.forceFit);
    const LinearFit& fit = *result.forceFit;
    EXPECT_EQ(fit.points, 21u);  // with the zero
    EXPECT_NEAR(result.c0_f, kC0_f, 3.0 * sweep.steps.input.baseline.meanStandardError + 1e-18);
    EXPECT_GT(fit.slopeStandardError, 0.0);
    EXPECT_LT(std::abs(fit.slope - kSensitivity_f_per_n), 3.0 * fit.slopeStandardError);
    EXPECT_LT(fit.slopeStandardError / kSensitivity_f_per_n, 1e-3);  // 4 fF of noise over 1.8 pF
    ASSERT_TRUE(result.hysteresis);
    EXPECT_LT(*result.hysteresis, 0.005);
    EXPECT_TRUE(result.cautions.empty());
}

// Over many noise seeds the stated ± of a noise-only sweep covers the
// true sensitivity as a standard uncertainty does.
TEST(CapacitiveSweepTest, TheStatedUncertaintyCoversTheTrueSensitivity)
{
    unsigned within1 = 0, within2 = 0;
    constexpr unsigned kRuns = 200;
    for (unsigned seed = 1; seed <= kRuns; ++seed) {
        Sweep lagging;  // the lag found and taken out costs the ± nothing
        lagging.lag_s = 0.4;
        const auto result = calibrateCapacitive(stepsFromSweep(record(lagging, seed), settings()).steps.input, "b", "");
        const double z = std::abs(result.forceFit->slope - kSensitivity_f_per_n) / result.forceFit->slopeStandardError;
        within1 += z <= 1.0;
        within2 += z <= 2.0;
    }
    // 68 % and 95 % within binomial 3σ limits of 200 draws (±10 %, ±5 %);
    // the bins' capacitance at their middle is read through a line, which
    // makes a point's noise a little larger than a mean's: no wider.
    EXPECT_GE(within1, 116);
    EXPECT_LE(within1, 156);
    EXPECT_GE(within2, 180);
}

// A beam settling in 0.4 s reads loading and unloading apart by the force
// the sweep moves in that time: 2 × 0.4 s × 75 µN/s of the 1.5 mN span,
// 4 %. The lag is found, taken out, and the silicone-free beam is again on
// one line: no hysteresis, its sensitivity within its ±.
TEST(CapacitiveSweepTest, FindsTheBeamsLagAndTakesItOut)
{
    Sweep lagging;
    lagging.lag_s = 0.4;
    const SweepSteps sweep = stepsFromSweep(record(lagging), settings());
    EXPECT_NEAR(sweep.lag_s, 0.4, 0.01);
    const auto result = calibrateCapacitive(sweep.steps.input, "beam", "");
    const LinearFit& fit = *result.forceFit;
    ASSERT_TRUE(result.hysteresis);
    EXPECT_LT(*result.hysteresis, 0.005);
    EXPECT_LT(std::abs(fit.slope - kSensitivity_f_per_n), 3.0 * fit.slopeStandardError);

    // Without it, the 4 % stays as hysteresis.
    SweepSettings kept = settings();
    kept.maxLag_s = 0.0;
    const auto raw = calibrateCapacitive(stepsFromSweep(record(lagging), kept).steps.input, "beam", "");
    EXPECT_NEAR(*raw.hysteresis, 2.0 * 0.4 * kPeak_n / 20.0 / kPeak_n, 0.01);
}

TEST(CapacitiveSweepTest, TwoCyclesTurnThreeTimesAndFillTheSameBins)
{
    Sweep twice;
    twice.cycles = 2;
    const SweepSteps sweep = stepsFromSweep(record(twice), settings());
    EXPECT_EQ(sweep.turns, 3u);
    ASSERT_EQ(sweep.steps.steps.size(), 20u);
    for (const auto& step : sweep.steps.steps) EXPECT_GE(step.window.count, 2u * 10u);  // from both cycles
    const auto result = calibrateCapacitive(sweep.steps.input, "beam", "");
    EXPECT_LT(std::abs(result.forceFit->slope - kSensitivity_f_per_n), 3.0 * result.forceFit->slopeStandardError);
}

// Pushed up and never taken off (the recording stopped at the peak): the
// loading points alone, and the calibration says what that leaves out.
TEST(CapacitiveSweepTest, ASweepThatNeverComesBackGivesLoadingPointsAndACaution)
{
    CapacitiveRecording r = record({});
    const auto peak = static_cast<std::size_t>((10.0 + 20.0) * 10.0);  // 10 s at rest, 20 s up, at 10 Hz
    r.t_s.resize(peak);
    r.capacitance_f.resize(peak);
    r.load_n.resize(peak);
    const SweepSteps sweep = stepsFromSweep(r, settings());
    EXPECT_EQ(sweep.turns, 0u);
    EXPECT_FALSE(sweep.steps.input.finalBaseline);
    ASSERT_FALSE(sweep.steps.steps.empty());
    for (const auto& step : sweep.steps.steps) EXPECT_TRUE(step.loading);
    const auto result = calibrateCapacitive(sweep.steps.input, "beam", "");
    EXPECT_FALSE(result.hysteresis);
    ASSERT_EQ(result.cautions.size(), 1u);
    EXPECT_NE(result.cautions.front().find("never removed"), std::string::npos) << result.cautions.front();
}

TEST(CapacitiveSweepTest, RefusesWhatIsNoCalibrationSweep)
{
    Sweep loadedFromTheStart;
    loadedFromTheStart.rest_s = 0.2;
    EXPECT_THROW(stepsFromSweep(record(loadedFromTheStart), settings()), std::invalid_argument);

    CapacitiveRecording flat = record({});
    std::ranges::fill(flat.load_n, 1e-3);
    EXPECT_THROW(stepsFromSweep(flat, settings()), std::invalid_argument);

    Sweep noisy;
    noisy.capacitanceNoise_f = 100e-15;  // five times the stable σ: the start never settles
    EXPECT_THROW(stepsFromSweep(record(noisy), settings()), std::invalid_argument);

    CapacitiveRecording untimed = record({});
    untimed.t_s.clear();
    EXPECT_THROW(stepsFromSweep(untimed, settings()), std::invalid_argument);
}

// The pairing against a reference known everywhere: a force rising 2 N/s,
// sampled at 10 Hz with a second missing; beam samples inside it, in the
// gap and beyond the ends.
TEST(ReferencePairingTest, InterpolatesInsideTheReferenceAndMakesNothingUpAcrossItsGapsOrEnds)
{
    std::vector<double> rt, rf;
    for (int i = 0; i <= 100; ++i) {
        const double t = 0.1 * i;
        rt.push_back(t);
        rf.push_back(t >= 4.0 && t < 5.0 ? std::nan("") : 2.0 * t);  // a gap from 4 s to 5 s
    }
    const std::vector<double> bt{-0.5, 0.05, 1.234, 3.95, 4.5, 5.05, 9.999, 10.5};
    const std::vector<double> bc{1, 2, 3, 4, 5, 6, 7, 8};
    const PairedSweep paired = pairWithReference(bt, bc, rt, rf, 10.0);
    EXPECT_EQ(paired.outsideReference, 4u);  // before, in the gap (twice: 3.95 and 4.5 lie between 3.9 and 5.0), after
    ASSERT_EQ(paired.recording.t_s.size(), 4u);
    const std::vector<double> expected{0.1, 2.468, 10.1, 19.998};
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(paired.recording.load_n[i], expected[i], 1e-9) << i;
    EXPECT_EQ(paired.recording.capacitance_f, (std::vector<double>{2, 3, 6, 7}));
    EXPECT_NEAR(paired.steepest_n_per_s, 2.0, 1e-9);
    EXPECT_THROW(pairWithReference(bt, bc, rt, rf, 0.0), std::invalid_argument);
    EXPECT_THROW(pairWithReference({bt.data(), 1}, {bc.data(), 1}, rt, rf, 10.0), std::invalid_argument);
}
