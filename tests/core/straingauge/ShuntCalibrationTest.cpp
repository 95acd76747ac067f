// Shunt calibration (issue 39): the strain a shunted bridge shows, checked
// by hand against the published figure (a 100 kΩ shunt across a 350 Ω
// gauge simulates about −1744 µε at GF 2.0 on a quarter bridge) and, for
// every bridge type, against the Wheatstone bridge solved from its four
// resistances and read through the channel's own conversion.
#include "core/straingauge/ShuntCalibration.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope::core::straingauge;

TEST(ShuntCalibration, AQuarterBridgeShowsThePublishedFigure)
{
    // y = −350/100 350 = −0.00348779…; ε = y/2 = −1743.896 µε.
    EXPECT_NEAR(shuntStrain(BridgeType::Quarter, 350.0, 100e3, 2.0) * 1e6, -1743.896, 1e-3);
    // 120 Ω gauges with a 59 880 Ω shunt: the textbook 1000 µε at GF 2 (120/60 000/2).
    EXPECT_NEAR(shuntStrain(BridgeType::Quarter, 120.0, 59880.0, 2.0) * 1e6, -1000.0, 1e-9);
}

TEST(ShuntCalibration, EveryBridgeTypeAgreesWithTheBridgeSolvedFromItsResistances)
{
    const double rg = 350.0, gf = 2.1;
    for (const double rs : {10e3, 49.9e3, 100e3, 1e6}) {
        // The shunted arm R1 = R_g‖R_s beside R2 = R_g; the other half at ½: V_r = R1/(R1 + R2) − ½.
        const double r1 = rg * rs / (rg + rs);
        const double ratio = r1 / (r1 + rg) - 0.5;
        for (const BridgeType type : {BridgeType::Quarter, BridgeType::HalfBending, BridgeType::FullBending}) {
            BridgeSettings bridge;
            bridge.type = type;
            bridge.gaugeFactor = gf;
            const StrainGaugeChain chain(AdcSettings{}, bridge);
            const double shown = chain.relativeChange(ratio) / gf;  // what the channel reads
            EXPECT_NEAR(shuntStrain(type, rg, rs, gf), shown, 1e-15 + 1e-12 * std::abs(shown))
                << "R_s " << rs << ", bridge " << static_cast<int>(type);
        }
    }
}

TEST(ShuntCalibration, TheCheckPassesWithinItsToleranceAndSaysHowFarOff)
{
    const double expected = shuntStrain(BridgeType::HalfBending, 350.0, 100e3, 2.0);
    const auto good = checkShunt(expected, expected * 1.004, 0.01);
    EXPECT_TRUE(good.passed);
    EXPECT_NEAR(good.deviation, 0.004, 1e-12);
    // A gauge factor 5 % off reads 5 % off: it fails a 1 % check.
    const auto bad = checkShunt(expected, expected * 2.0 / 2.1, 0.01);
    EXPECT_FALSE(bad.passed);
    EXPECT_NEAR(bad.deviation, 2.0 / 2.1 - 1.0, 1e-12);
    EXPECT_THROW(shuntStrain(BridgeType::Quarter, 0.0, 100e3, 2.0), std::invalid_argument);
    EXPECT_THROW(shuntStrain(BridgeType::Quarter, 350.0, -1.0, 2.0), std::invalid_argument);
    EXPECT_THROW(checkShunt(0.0, 1.0, 0.01), std::invalid_argument);
}
