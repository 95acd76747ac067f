// Beam model against the paper's specimens and hand calculations.
#include "core/sensors/CantileverBeam.h"

#include <gtest/gtest.h>

#include <stdexcept>

using tactiscope::core::sensors::CantileverBeam;

TEST(CantileverBeam, ThePapersFourSpecimensHaveTheirTableStiffness)
{
    // Perspex, E = 3 GPa, w = 10 mm, t = 2 mm: k = 0.06/L³ (Table 1).
    const std::pair<double, double> specimens[] = {{0.100, 60.0}, {0.080, 117.0}, {0.070, 174.0}, {0.050, 480.0}};
    for (const auto& [length, stiffness] : specimens) {
        const CantileverBeam beam({length, 0.01, 0.002, 3e9});
        EXPECT_NEAR(beam.stiffness_n_per_m(), stiffness, 0.01 * stiffness) << "L = " << length;
    }
}

TEST(CantileverBeam, StrainAndDeflectionPerNewtonByHand)
{
    // The paper's high beam: L = 50 mm, w = 10 mm, t = 3 mm, E = 3 GPa.
    const CantileverBeam beam({0.05, 0.01, 0.003, 3e9});
    EXPECT_DOUBLE_EQ(beam.stiffness_n_per_m(), 1620.0);           // 3e9·0.01·27e-9 / (4·1.25e-4)
    EXPECT_NEAR(beam.rootStrainPerNewton(), 1.0 / 900.0, 1e-18);  // 6·0.05 / (3e9·0.01·9e-6)
    EXPECT_NEAR(beam.tipDeflectionPerNewton_m(), 1.0 / 1620.0, 1e-18);
}

TEST(CantileverBeam, RejectsNonPositiveDimensions)
{
    EXPECT_THROW(CantileverBeam({0.0, 0.01, 0.002, 3e9}), std::invalid_argument);
    EXPECT_THROW(CantileverBeam({0.05, -0.01, 0.002, 3e9}), std::invalid_argument);
    EXPECT_THROW(CantileverBeam({0.05, 0.01, 0.002, 0.0}), std::invalid_argument);
}
