// Capacitive calibration: the paper's own figures, and recovery of slope,
// C0 and detection limit from synthetic data with known noise.
#include "core/calibration/CapacitiveCalibration.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <stdexcept>

using namespace tactiscope::core::calibration;

namespace {

WindowStatistics baselineOf(double c0_f, double sigma_f, double middle_s = 0.0)
{
    WindowStatistics w;
    w.mean = c0_f;
    w.sigma = sigma_f;
    w.start_s = middle_s - 1.0;
    w.end_s = middle_s + 1.0;
    return w;
}

}  // namespace

TEST(CapacitiveCalibration, ThePapersFiguresFollowFromItsFit)
{
    // ΔC = 1.660 pF/mN · F exactly, C0 = 51.44 pF, 3 mm × 3 mm plate.
    CapacitiveCalibrationInput in;
    in.baseline = baselineOf(51.44e-12, 0.0);
    in.contactArea_m2 = 9e-6;
    for (int mgf = 10; mgf <= 150; mgf += 10) {
        const double force = mgf * kMilligramForce_n;
        in.steps.push_back({force, std::nullopt, 51.44e-12 + 1.660e-9 * force, 0.0, true});
    }
    const auto r = calibrateCapacitive(in, "No. 1", "tester");
    EXPECT_NEAR(r.forceFit->slope * 1e9, 1.660, 1e-9);                  // pF/mN
    EXPECT_NEAR(*r.relativeSensitivity_per_n * 1e-3, 0.0323, 0.00005);  // ΔC/C0 per mN
    EXPECT_NEAR(*r.pressureSensitivity_per_pa * 1e3, 0.290, 0.001);     // per kPa on 9 mm²
    // 2 mgf (the paper's paper scrap) gives about 0.03 pF.
    EXPECT_NEAR(r.forceFit->slope * 2 * kMilligramForce_n * 1e12, 0.0326, 0.0005);
    EXPECT_NEAR(*r.record.value("sensitivity_pf_per_mn"), 1.660, 1e-9);
}

TEST(CapacitiveCalibration, ForceStepsAloneGiveADisplacementLimitThroughTheStiffness)
{
    // σ 0.004 pF, 1.8 pF/mN: 3σ/S = 0.012/1.8 mN = 6.667 µN; at 0.5 N/m
    // that is a tip displacement of 13.33 µm. Fitted points: the baseline
    // first, then the steps.
    CapacitiveCalibrationInput in;
    in.baseline = baselineOf(51.44e-12, 4e-15);
    in.stiffness_n_per_m = 0.5;
    for (int mgf : {50, 100}) {
        const double force = mgf * kMilligramForce_n;
        in.steps.push_back({force, std::nullopt, 51.44e-12 + 1.8e-9 * force, 0.0, true});
    }
    const auto r = calibrateCapacitive(in, "No. 1", "tester");
    EXPECT_NEAR(*r.detectionLimit_n, 6.6667e-6, 1e-9);
    EXPECT_NEAR(*r.detectionLimit_m, 13.333e-6, 1e-8);
    EXPECT_NEAR(*r.record.value("detection_limit_mm"), 13.333e-3, 1e-5);
    ASSERT_EQ(r.fitForce_n.size(), 3u);
    EXPECT_EQ(r.fitForce_n[0], 0.0);
    EXPECT_EQ(r.fitForce_n[2], 100 * kMilligramForce_n);
    EXPECT_NEAR(r.fitDelta_f[2], 1.8e-9 * 100 * kMilligramForce_n, 1e-18);
}

TEST(CapacitiveCalibration, RecoversSlopeC0AndDetectionLimitFromNoisyData)
{
    const double c0 = 51.44e-12, slope = 1.8e-9, sigma = 4e-15;  // 0.004 pF noise
    std::mt19937 random(11);
    std::normal_distribution<double> noise(0.0, sigma);
    CapacitiveCalibrationInput in;
    double baselineSum = 0.0;
    const int baselineSamples = 400;
    for (int i = 0; i < baselineSamples; ++i) baselineSum += c0 + noise(random);
    in.baseline = baselineOf(baselineSum / baselineSamples, sigma);
    for (int mgf = 10; mgf <= 150; mgf += 10) {
        const double force = mgf * kMilligramForce_n;
        double mean = 0.0;
        for (int i = 0; i < 20; ++i) mean += (c0 + slope * force + noise(random)) / 20.0;
        in.steps.push_back({force, std::nullopt, mean, 0.0, true});
    }
    const auto r = calibrateCapacitive(in, "b", "o");
    EXPECT_NEAR(r.c0_f, c0, 1e-15);
    EXPECT_NEAR(r.forceFit->slope, slope, 0.01 * slope);
    EXPECT_GE(r.forceFit->rSquared, 0.999);
    EXPECT_NEAR(*r.detectionLimit_n, 3 * sigma / slope, 0.02 * 3 * sigma / slope);  // ≈ 6.7 µN
}

TEST(CapacitiveCalibration, RemovesLinearDriftAndMeasuresHysteresis)
{
    // Baseline drifts by +0.1 pF over 100 s; unloading reads 2 % of full
    // scale (0.5 pF) higher than loading at each weight.
    const double c0 = 50e-12, drift = 1e-15, perNewton = 2e-9;
    CapacitiveCalibrationInput in;
    in.baseline = baselineOf(c0, 1e-15, 0.0);
    in.finalBaseline = baselineOf(c0 + 100.0 * drift, 1e-15, 100.0);
    const double forces[] = {0.5e-3, 1.0e-3, 1.5e-3, 1.0e-3, 0.5e-3};
    const bool loading[] = {true, true, true, false, false};
    for (int i = 0; i < 5; ++i) {
        const double t = 20.0 + 15.0 * i;
        const double extra = loading[i] ? 0.0 : 0.02 * perNewton * 1.5e-3;
        in.steps.push_back({forces[i], std::nullopt, c0 + drift * t + perNewton * forces[i] + extra, t, loading[i]});
    }
    const auto r = calibrateCapacitive(in, "b", "o");
    EXPECT_NEAR(r.drift_f_per_s, drift, 1e-20);
    EXPECT_NEAR(r.forceFit->slope, perNewton, 0.02 * perNewton);
    ASSERT_TRUE(r.hysteresis.has_value());
    EXPECT_NEAR(*r.hysteresis, 0.02, 1e-6);
}

TEST(CapacitiveCalibration, DisplacementsGiveTheirOwnSensitivityAndDetectionLimit)
{
    CapacitiveCalibrationInput in;
    in.baseline = baselineOf(51.44e-12, 5e-15);
    for (double mm : {0.5, 1.0, 1.5, 2.0, 3.0})
        in.steps.push_back({std::nullopt, mm * 1e-3, 51.44e-12 + 0.533e-9 * mm * 1e-3, 0.0, true});
    const auto r = calibrateCapacitive(in, "b", "o");
    EXPECT_FALSE(r.forceFit.has_value());
    EXPECT_NEAR(r.displacementFit->slope * 1e9, 0.533, 1e-9);  // pF/mm
    EXPECT_NEAR(*r.detectionLimit_m, 3 * 5e-15 / 0.533e-9, 1e-12);
    EXPECT_THROW(calibrateCapacitive(CapacitiveCalibrationInput{}, "b", "o"), std::invalid_argument);
}

TEST(CapacitiveCalibration, StableMeansReadOutNoiseButNotACreepingBeam)
{
    const StabilitySettings settings = capacitiveStabilityDefaults();
    EXPECT_DOUBLE_EQ(settings.window_s, 2.0);
    // 2 s at 10 Hz, the paper's meter; the simulator's 4 fF white noise is
    // a square wave of ±4 fF here (σ 4 fF exactly, no slope).
    auto judge = [&](double slope_f_per_s) {
        StabilityMonitor monitor(settings);
        std::optional<WindowStatistics> last;
        for (int i = 0; i <= 20; ++i)
            if (auto s = monitor.push(0.1 * i, 51.44e-12 + slope_f_per_s * 0.1 * i + (i % 2 ? 4e-15 : -4e-15)))
                last = s;
        return last.value();
    };
    EXPECT_TRUE(judge(0.0).stable);
    // Creep of 10 fF/s, twice the limit.
    EXPECT_FALSE(judge(10e-15).stable);
}

TEST(CapacitiveCalibration, ThePointsMayLieFurtherOffTheLineForTheSiliconesHysteresis)
{
    EXPECT_DOUBLE_EQ(capacitiveCredibilityLimits().maximumOffLine, 0.03);
    EXPECT_EQ(capacitiveCredibilityLimits().minimumPoints, CredibilityLimits{}.minimumPoints);
}
