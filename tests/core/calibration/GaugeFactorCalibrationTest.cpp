// Gauge-factor calibration recovers a known factor from noisy synthetic
// loads on a cantilever of known geometry.
#include "core/calibration/GaugeFactorCalibration.h"

#include <gtest/gtest.h>

#include <cmath>
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

    const auto result = calibrateGaugeFactor(beam, nominal, zero, loads, "low beam", "tester");
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
    EXPECT_THROW(calibrateGaugeFactor(beam, chain, 0.0, {{0.1, 0.0, 100.0}}, "b", "o"), std::invalid_argument);
    EXPECT_THROW(calibrateGaugeFactor(beam, chain, 0.0, {{0.1, 0.001, 100.0}, {0.2, 0.0, 200.0}}, "b", "o"),
                 std::invalid_argument);
}
