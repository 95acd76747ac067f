// The two-beam compliance probe: the paper's sensor, Q ↔ k_o, out-of-range
// states, sensitivity and the design quantities of section 2.2.3.
#include "core/sensors/CompliancePair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace tactiscope::core::sensors;

namespace {

// The paper's sensor: Perspex, w = 10 mm, L = 50 mm, t_h = 3 mm, t_l = 1 mm.
CompliancePair paperSensor()
{
    return CompliancePair(CantileverBeam({0.05, 0.01, 0.003, 3e9}), CantileverBeam({0.05, 0.01, 0.001, 3e9}));
}

}  // namespace

TEST(CompliancePair, ThePapersSensorByHand)
{
    const CompliancePair pair = paperSensor();
    EXPECT_DOUBLE_EQ(pair.kHigh_n_per_m(), 1620.0);  // 3e9·0.01·(3e-3)³ / (4·0.05³)
    EXPECT_DOUBLE_EQ(pair.kLow_n_per_m(), 60.0);     // 3e9·0.01·(1e-3)³ / (4·0.05³)
    EXPECT_DOUBLE_EQ(pair.qMax(), 27.0);             // (t_h/t_l)³
    // Q(117) = 1620·177 / (60·1737) = 2.7513…
    EXPECT_NEAR(pair.forceRatio(117.0), 1620.0 * 177.0 / (60.0 * 1737.0), 1e-12);
    EXPECT_DOUBLE_EQ(pair.forceRatio(0.0), 1.0);
}

TEST(CompliancePair, ForceRatioAndStiffnessInvertEachOtherOverTheRange)
{
    const CompliancePair pair = paperSensor();
    for (double k = 1.0; k <= 500.0; k += 7.0) {
        const StiffnessReading r = pair.objectStiffness(pair.forceRatio(k));
        ASSERT_EQ(r.range, ComplianceRange::InRange);
        EXPECT_NEAR(r.objectStiffness_n_per_m, k, 1e-9 * k) << "k_o = " << k;
    }
}

TEST(CompliancePair, OutOfRangeIsAStateNotANumber)
{
    const CompliancePair pair = paperSensor();
    EXPECT_EQ(pair.objectStiffness(1.0).range, ComplianceRange::Below);
    EXPECT_EQ(pair.objectStiffness(0.5).range, ComplianceRange::Below);
    EXPECT_EQ(pair.objectStiffness(-3.0).range, ComplianceRange::Below);
    EXPECT_EQ(pair.objectStiffness(std::nan("")).range, ComplianceRange::Below);
    EXPECT_EQ(pair.objectStiffness(pair.qMax()).range, ComplianceRange::Above);
    EXPECT_EQ(pair.objectStiffness(40.0).range, ComplianceRange::Above);
    EXPECT_EQ(pair.objectStiffness(26.9).range, ComplianceRange::InRange);
}

TEST(CompliancePair, SensitivityIsTheDerivativeOfTheForceRatio)
{
    const CompliancePair pair = paperSensor();
    for (double k : {10.0, 60.0, 200.0, 480.0}) {
        const double h = 1e-3;
        const double numeric = (pair.forceRatio(k + h) - pair.forceRatio(k - h)) / (2 * h);
        EXPECT_NEAR(pair.sensitivity_m_per_n(k), numeric, 1e-7) << "k_o = " << k;
    }
    // eq. 5 at k_o = 0: k_h(k_h − k_l)/(k_l·k_h²) = 1560/(60·1620)
    EXPECT_NEAR(pair.sensitivity_m_per_n(0.0), 1560.0 / (60.0 * 1620.0), 1e-15);
}

TEST(CompliancePair, DesignRatiosFollowEquationsEightAndEleven)
{
    const CompliancePair pair = paperSensor();
    const DesignPoint p = pair.designPoint(117.0);
    EXPECT_NEAR(p.strainRatio, 9.0 / p.q, 1e-12);       // (1/Q)(t_h/t_l)²
    EXPECT_NEAR(p.deflectionRatio, 27.0 / p.q, 1e-12);  // (1/Q)(t_h/t_l)³
    // Eq. 12: Δ_l/Δ_h = (ε_l/ε_h)(t_h/t_l)
    EXPECT_NEAR(p.deflectionRatio, p.strainRatio * 3.0, 1e-12);
    // Pressed 1 m: F_H = k_h·k_o/(k_h + k_o), tip deflection k_o/(k_h + k_o).
    EXPECT_NEAR(p.deflectionHigh, 117.0 / 1737.0, 1e-12);
    EXPECT_NEAR(p.strainHigh_per_m, 1620.0 * 117.0 / 1737.0 / 900.0, 1e-12);
}

TEST(CompliancePair, LongerBeamsRaiseQAndLowerTheStrainRatio)
{
    // Section 2.2.3, Figs 5 and 6, over the working range.
    const CompliancePair base = paperSensor();
    const double lengths[] = {0.040, 0.050, 0.060};
    for (double k : {50.0, 250.0, 500.0}) {
        double lastQ = 0.0, lastStrainRatio = 1e9;
        for (double L : lengths) {
            const DesignPoint p = base.withLength(L).designPoint(k);
            EXPECT_GT(p.q, lastQ);
            EXPECT_LT(p.strainRatio, lastStrainRatio);
            lastQ = p.q;
            lastStrainRatio = p.strainRatio;
        }
    }
    // Eq. 13 with L³·k_o (the paper prints L·k_o): Q = C1·(L³k_o + C2)/(L³k_o + C3)
    // with C1 = (t_h/t_l)³, C2 = 3·E·I_l, C3 = 3·E·I_h, I = w·t³/12.
    const double L = 0.06, k = 150.0, E = 3e9, w = 0.01;
    const double C2 = 3 * E * w * 1e-9 / 12, C3 = 3 * E * w * 27e-9 / 12;
    EXPECT_NEAR(base.withLength(L).forceRatio(k), 27.0 * (L * L * L * k + C2) / (L * L * L * k + C3), 1e-12);
    const auto curve = base.designCurve(0.0, 500.0, 11);
    ASSERT_EQ(curve.size(), 11u);
    EXPECT_DOUBLE_EQ(curve.back().objectStiffness_n_per_m, 500.0);
}

TEST(CompliancePair, TheHighBeamMustBeTheStifferOne)
{
    EXPECT_THROW(CompliancePair(CantileverBeam({0.05, 0.01, 0.001, 3e9}), CantileverBeam({0.05, 0.01, 0.003, 3e9})),
                 std::invalid_argument);
}
