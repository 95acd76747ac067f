// Readout of force, displacement and ΔC/C0, and the unloaded-only drift rule.
#include "core/capacitive/CapacitiveReadout.h"

#include <gtest/gtest.h>

using namespace tactiscope::core::capacitive;

namespace {

const CapacitiveSensitivity kSensitivity{51.44e-12, 1.66e-9, 0.533e-9};  // pF/mN and pF/mm in SI

}  // namespace

TEST(CapacitiveReadout, ScalesTheChangeIntoForceDisplacementAndRelativeChange)
{
    CapacitiveReadout readout(kSensitivity, {});
    const auto r = readout.push(0.0, 51.44e-12 + 0.166e-12);  // +0.166 pF
    EXPECT_NEAR(r.force_n, 0.1e-3, 1e-12);                    // 0.1 mN
    EXPECT_NEAR(r.displacement_m, 0.166 / 0.533 * 1e-3, 1e-12);
    EXPECT_NEAR(r.relativeChange, 0.166 / 51.44, 1e-12);
}

TEST(CapacitiveReadout, FollowsDriftOnlyWhileUnloaded)
{
    const double sigma = 4e-15;
    CapacitiveReadout readout(kSensitivity, {sigma, 3.0, 2.0, 30.0});
    // 60 s unloaded with a baseline drifting by 0.2 fF/s (within 3σ of C0 at
    // every step): C0 follows.
    double c = 51.44e-12;
    CapacitiveReading r;
    for (int i = 0; i <= 600; ++i) {
        c = 51.44e-12 + 0.2e-15 * i * 0.1;
        r = readout.push(i * 0.1, c);
    }
    EXPECT_TRUE(r.unloaded);
    EXPECT_NEAR(r.c0_f, c, 6e-15);
    // A weight comes on: C0 freezes, the force reads right.
    const double frozen = readout.c0_f();
    for (int i = 601; i <= 700; ++i) r = readout.push(i * 0.1, frozen + 1.66e-9 * 0.5e-3);
    EXPECT_FALSE(r.unloaded);
    EXPECT_DOUBLE_EQ(readout.c0_f(), frozen);
    EXPECT_NEAR(r.force_n, 0.5e-3, 1e-9);
    // Tare while loaded makes the present load the new zero.
    readout.tare();
    EXPECT_NEAR(readout.push(70.1, frozen + 1.66e-9 * 0.5e-3).force_n, 0.0, 1e-6);
}
