// The capacitive uniform-strength beam against the paper's theory for its
// sensor No. 1 (l = 15 mm, b = 5 mm, 2.368 mm Eco-flex at 83 kPa, α = 0.6,
// hydrogel electrodes 0.462 mm at 1.8 kPa, a 15 µm Eco-flex dielectric,
// C0 = 51.44 pF).
#include "core/sensors/CapacitiveBeam.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core::sensors;

namespace {

CapacitiveBeamGeometry sensorNo1()
{
    CapacitiveBeamGeometry g;
    g.beam = {0.015, 0.005, 0.002368, 83e3, 0.6};
    g.sheetLayers = {
        {"inner electrode", 0.000462, 1800}, {"dielectric", 0.000015, 83e3}, {"outer electrode", 0.000462, 1800}};
    g.c0_f = 51.44e-12;
    return g;
}

}  // namespace

TEST(CapacitiveBeam, ReproducesThePapersTheoryForSensorNumberOne)
{
    const CapacitiveBeam beam(sensorNo1());
    // Theory in the paper: 3.22 mm/mN at the tip, i.e. k_s = 0.31 N/m.
    EXPECT_NEAR(beam.tipDeflectionPerNewton_m(), 3.22, 0.01 * 3.22);
    EXPECT_NEAR(beam.stiffness_n_per_m(), 0.31, 0.01 * 0.31);
    // Measured 1.660 pF/mN and 0.533 pF/mm, which the paper says the theory
    // exceeds by 8.7 % and 3.9 %: 1.804 pF/mN and 0.554 pF/mm.
    EXPECT_NEAR(beam.capacitancePerNewton_f_per_n() * 1e9, 1.660 * 1.087, 0.01 * 1.80);
    EXPECT_NEAR(beam.capacitancePerMetre_f_per_m() * 1e9, 0.533 * 1.039, 0.01 * 0.554);
}

TEST(CapacitiveBeam, SegmentsAndTheSheetStrainFollowTheEquations)
{
    const CapacitiveBeam beam(sensorNo1());
    // Segment 2 is the bare beam: A_2 = E·h³/12.
    EXPECT_NEAR(beam.segment2().bendingStiffnessPerWidth_n_m, 83e3 * 0.002368 * 0.002368 * 0.002368 / 12.0, 1e-15);
    EXPECT_DOUBLE_EQ(beam.interface_m(), 0.000462 * 2 + 0.000015);  // z_U below three sheet layers
    // The neutral axis lies in the (much stiffer) beam, so the sheet stretches.
    EXPECT_GT(beam.segment1().neutralAxis_m, beam.interface_m());
    const auto& s1 = beam.segment1();
    EXPECT_NEAR(beam.sheetStrainPerNewton(),
                (s1.neutralAxis_m - beam.interface_m()) * 0.015 / (s1.bendingStiffnessPerWidth_n_m * 0.005), 1e-12);
    EXPECT_NEAR(beam.capacitancePerNewton_f_per_n(), 51.44e-12 * beam.sheetStrainPerNewton(), 1e-24);
    // Eq. 31 is eq. 13 over eq. 28.
    EXPECT_NEAR(beam.capacitancePerMetre_f_per_m(),
                beam.capacitancePerNewton_f_per_n() / beam.tipDeflectionPerNewton_m(), 1e-20);
}

TEST(CapacitiveBeam, DoubleLayersInSeriesReduceTheCapacitanceSlightly)
{
    // C = C_d/(2C_d/C_EDL + 1): 51.44 pF against 10 µF layers barely moves.
    EXPECT_NEAR(seriesDoubleLayerCapacitance(51.44e-12, 10e-6), 51.44e-12 / (2 * 51.44e-12 / 10e-6 + 1), 1e-25);
    EXPECT_NEAR(seriesDoubleLayerCapacitance(100e-12, 100e-12), 100e-12 / 3.0, 1e-25);
    auto g = sensorNo1();
    const double plain = CapacitiveBeam(g).capacitancePerNewton_f_per_n();
    g.doubleLayer_f = 1e-9;  // a poor, 1 nF double layer
    const double factor = 2 * 51.44e-12 / 1e-9 + 1;
    EXPECT_NEAR(CapacitiveBeam(g).capacitancePerNewton_f_per_n(), plain / (factor * factor), 1e-24);
}

TEST(CapacitiveBeam, RejectsNonPhysicalGeometry)
{
    auto g = sensorNo1();
    g.beam.sheetLengthRatio = 1.0;
    EXPECT_THROW(CapacitiveBeam{g}, std::invalid_argument);
    g = sensorNo1();
    g.sheetLayers.clear();
    EXPECT_THROW(CapacitiveBeam{g}, std::invalid_argument);
    g = sensorNo1();
    g.c0_f = 0.0;
    EXPECT_THROW(CapacitiveBeam{g}, std::invalid_argument);
}
