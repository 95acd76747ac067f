// Layered sections against the textbook single-layer result and a
// transformed-section hand calculation.
#include "core/sensors/LayeredSection.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core::sensors;

TEST(LayeredSection, OneLayerIsTheRectangularSection)
{
    const Layer layer[] = {{0.003, 2e9}};
    const auto s = sectionProperties(layer);
    EXPECT_NEAR(s.bendingStiffnessPerWidth_n_m, 2e9 * 0.003 * 0.003 * 0.003 / 12.0, 1e-12);  // E·h³/12
    EXPECT_NEAR(s.neutralAxis_m, 0.0015, 1e-15);                                             // mid-thickness
    EXPECT_DOUBLE_EQ(s.height_m, 0.003);
}

TEST(LayeredSection, TwoLayersMatchTheTransformedSectionMethod)
{
    // Bottom: 1 mm at 1 GPa; top: 2 mm at 3 GPa. Transformed section: the
    // neutral axis is the E-weighted centroid of the layers' centroids, and
    // A is Σ E·(h³/12 + h·d²) about it (parallel axes).
    const Layer layers[] = {{0.001, 1e9}, {0.002, 3e9}};
    const double w1 = 1e9 * 0.001, w2 = 3e9 * 0.002;
    const double zN = (w1 * 0.0005 + w2 * 0.002) / (w1 + w2);  // 1.7857 mm
    const double A = 1e9 * (1e-9 / 12.0) + w1 * (0.0005 - zN) * (0.0005 - zN) + 3e9 * (8e-9 / 12.0) +
                     w2 * (0.002 - zN) * (0.002 - zN);
    const auto s = sectionProperties(layers);
    EXPECT_NEAR(s.neutralAxis_m, zN, 1e-15);
    EXPECT_NEAR(s.bendingStiffnessPerWidth_n_m, A, 1e-12 * A);
    EXPECT_NEAR(A, 4.0119, 1e-4);  // by hand: 0.0833 + 1.6531 + 2 + 0.2755
}

TEST(LayeredSection, RejectsEmptyOrNonPhysicalStacks)
{
    EXPECT_THROW(sectionProperties(std::span<const Layer>{}), std::invalid_argument);
    const Layer bad[] = {{0.001, 0.0}};
    EXPECT_THROW(sectionProperties(bad), std::invalid_argument);
}
