// Gauge-factor calibration recovers a known factor from noisy synthetic
// loads on a cantilever of known geometry.
#include "core/calibration/GaugeFactorCalibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>

using namespace tactiscope::core;
using calibration::calibrateGaugeFactor;
using calibration::CalibrationLoad;

TEST(GaugeFactorCalibration, RecoversTheTrueFactorFromNoisyLoads)
{
    // The paper's low beam: 0.01 strain per newton (6·0.05 / (3e9·0.01·1e-6)).
    const sensors::CantileverBeam beam({0.05, 0.01, 0.001, 3e9});
    const straingauge::AdcSettings adc{16, 10.0, true, 200.0};
    const straingauge::StrainGaugeChain nominal(adc, {straingauge::BridgeType::Quarter, 5.0, 2.0});
    const straingauge::StrainGaugeChain truth(adc, {straingauge::BridgeType::Quarter, 5.0, 2.13});
    const double zero = 250.0;

    std::mt19937 random(5);
    std::normal_distribution<double> noise(0.0, 2.0);  // counts, on each step's mean
    std::vector<CalibrationLoad> loads;
    for (double grams : {5.0, 10.0, 20.0, 30.0, 40.0, 50.0}) {
        const double force = grams * 1e-3 * calibration::kStandardGravity_m_per_s2;
        loads.push_back({force, 0.0, truth.countsForStrain(force * 0.01, zero) + noise(random)});
    }
    // One step by tip deflection: 5 mm on a 60 N/m beam is 0.3 N.
    loads.push_back({0.0, 0.005, truth.countsForStrain(0.3 * 0.01, zero) + noise(random)});

    const auto result = calibrateGaugeFactor(beam, nominal, {zero}, loads, "low beam", "tester");
    EXPECT_NEAR(result.gaugeFactor, 2.13, 0.005 * 2.13);
    EXPECT_NEAR(result.deviationFromNominal, 0.065, 0.006);
    EXPECT_GT(result.strainFit.rSquared, 0.9999);
    EXPECT_LT(result.strainFit.slopeStandardError, 0.01);
    EXPECT_EQ(result.strainFit.points, 8u);  // the zero step and seven loads
    // counts per newton: d(counts)/dF ≈ counts per unit V_r · (GF·s/4)
    const double perNewton = nominal.counts(5.0) * 2.13 * 0.01 / 4.0;
    EXPECT_NEAR(result.countsPerNewton, perNewton, 0.01 * perNewton);
    // The fitted slope reads a 30 g load back to within 0.5 %.
    const double force = 0.030 * calibration::kStandardGravity_m_per_s2;
    EXPECT_NEAR(result.forceCalibration().force_n(truth.countsForStrain(force * 0.01, zero)), force, 0.005 * force);
    EXPECT_EQ(result.record.kind, "gauge_factor");
    EXPECT_EQ(result.record.sensorName, "low beam");
    EXPECT_NEAR(*result.record.value("gauge_factor"), result.gaugeFactor, 0.0);
    EXPECT_NE(result.record.toJson().find("\"r_squared\":"), std::string::npos);
}

TEST(GaugeFactorCalibration, RefusesTooFewOrAmbiguousLoads)
{
    const sensors::CantileverBeam beam({0.05, 0.01, 0.001, 3e9});
    const straingauge::StrainGaugeChain chain({}, {});
    EXPECT_THROW(calibrateGaugeFactor(beam, chain, {}, {{0.1, 0.0, 100.0}}, "b", "o"), std::invalid_argument);
    EXPECT_THROW(calibrateGaugeFactor(beam, chain, {}, {{0.1, 0.001, 100.0}, {0.2, 0.0, 200.0}}, "b", "o"),
                 std::invalid_argument);
}

namespace {

// The statistics of 1 s of a signal at 1 kHz under `settings`.
calibration::WindowStatistics judged(const calibration::StabilitySettings& settings, double (*signal)(double t_s))
{
    calibration::StabilityMonitor monitor(settings);
    std::optional<calibration::WindowStatistics> last;
    for (int i = 0; i <= 1000; ++i)
        if (auto statistics = monitor.push(i * 1e-3, signal(i * 1e-3))) last = statistics;
    return last.value();
}

}  // namespace

TEST(GaugeFactorCalibration, StableMeansAmplifierNoiseButNotASwingingOrSettlingBeam)
{
    // A ±10 V 16-bit ADC: full scale 2^15 = 32768 counts, so at most
    // 6.55 counts/s of drift and 32.8 counts of σ over 1 s.
    const straingauge::StrainGaugeChain chain({16, 10.0, true, 200.0},
                                              {straingauge::BridgeType::HalfBending, 5.0, 2.0});
    const auto settings = calibration::gaugeStabilityDefaults(chain);
    EXPECT_DOUBLE_EQ(settings.window_s, 1.0);
    EXPECT_DOUBLE_EQ(settings.maxDrift_per_s, 6.5536);
    EXPECT_DOUBLE_EQ(settings.maxNoise, 32.768);
    // Amplifier noise of ±3 counts (a square wave: σ 3 counts exactly).
    EXPECT_TRUE(
        judged(settings, [](double t) { return 120.0 + ((static_cast<int>(t * 1e3) % 2) ? 3.0 : -3.0); }).stable);
    // A beam still swinging 200 counts at 5 Hz: σ about 141 counts.
    EXPECT_FALSE(
        judged(settings, [](double t) { return 120.0 + 200.0 * std::sin(2 * std::numbers::pi * 5.0 * t); }).stable);
    // A beam still creeping 20 counts/s.
    EXPECT_FALSE(judged(settings, [](double t) { return 120.0 + 20.0 * t; }).stable);
}

TEST(GaugeFactorCalibration, AMeanWithinFivePerCentOfTheAdcLimitIsNoPoint)
{
    // 95 % of 32768 counts is 31129.6.
    const straingauge::StrainGaugeChain chain({16, 10.0, true, 200.0}, {straingauge::BridgeType::Quarter, 5.0, 2.0});
    EXPECT_FALSE(calibration::nearAdcLimit(31129.0, chain));
    EXPECT_TRUE(calibration::nearAdcLimit(31130.0, chain));
    EXPECT_TRUE(calibration::nearAdcLimit(-31130.0, chain));
    EXPECT_FALSE(calibration::nearAdcLimit(0.0, chain));
}
