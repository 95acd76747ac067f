// Uniform-strength capacitive beam model (seed 002, eqs 1–31).
#include "core/sensors/CapacitiveBeam.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::sensors {
namespace {

bool positive(double value)
{
    return std::isfinite(value) && value > 0.0;
}

}  // namespace

double seriesDoubleLayerCapacitance(double dielectric_f, double doubleLayer_f)
{
    return dielectric_f / (2.0 * dielectric_f / doubleLayer_f + 1.0);
}

CapacitiveBeam::CapacitiveBeam(const CapacitiveBeamGeometry& g)
    : m_g(g),
      m_interface_m(0.0)
{
    const auto& b = g.beam;
    if (!positive(b.length_m) || !positive(b.rootWidth_m) || !positive(b.thickness_m) || !positive(b.youngsModulus_pa))
        throw std::invalid_argument("capacitive beam: beam dimensions and modulus must be positive");
    if (!(b.sheetLengthRatio > 0.0 && b.sheetLengthRatio < 1.0))
        throw std::invalid_argument("capacitive beam: sheet_length_ratio must lie between 0 and 1");
    if (g.sheetLayers.empty()) throw std::invalid_argument("capacitive beam: the sheet needs at least one layer");
    if (!positive(g.c0_f)) throw std::invalid_argument("capacitive beam: C0 must be positive");
    if (g.doubleLayer_f && !positive(*g.doubleLayer_f))
        throw std::invalid_argument("capacitive beam: the double-layer capacitance must be positive");

    // Paper z order: outermost sheet layer at z = 0, then inward, the beam last.
    std::vector<Layer> stack;
    for (auto it = g.sheetLayers.rbegin(); it != g.sheetLayers.rend(); ++it) {
        stack.push_back({it->thickness_m, it->youngsModulus_pa});
        m_interface_m += it->thickness_m;
    }
    stack.push_back({b.thickness_m, b.youngsModulus_pa});
    m_segment1 = sectionProperties(stack);
    const Layer beamOnly[] = {{b.thickness_m, b.youngsModulus_pa}};
    m_segment2 = sectionProperties(beamOnly);
}

double CapacitiveBeam::sheetStrainPerNewton() const
{
    const auto& b = m_g.beam;
    return (m_segment1.neutralAxis_m - m_interface_m) * b.length_m /
           (m_segment1.bendingStiffnessPerWidth_n_m * b.rootWidth_m);
}

double CapacitiveBeam::capacitancePerNewton_f_per_n() const
{
    const double dielectric = m_g.c0_f * sheetStrainPerNewton();
    if (!m_g.doubleLayer_f) return dielectric;
    // d/dC_d of C_d/(2C_d/C_EDL + 1) is 1/(2C_d/C_EDL + 1)²: the double
    // layers scale small changes of the dielectric's capacitance.
    const double factor = 2.0 * m_g.c0_f / *m_g.doubleLayer_f + 1.0;
    return dielectric / (factor * factor);
}

double CapacitiveBeam::tipDeflectionPerNewton_m() const
{
    const auto& b = m_g.beam;
    const double a = b.sheetLengthRatio;
    const double l3 = b.length_m * b.length_m * b.length_m;
    return (2.0 * a - a * a) * l3 / (2.0 * m_segment1.bendingStiffnessPerWidth_n_m * b.rootWidth_m) +
           (1.0 - a) * (1.0 - a) * l3 / (3.0 * m_segment2.bendingStiffnessPerWidth_n_m * b.rootWidth_m);
}

double CapacitiveBeam::stiffness_n_per_m() const
{
    return 1.0 / tipDeflectionPerNewton_m();
}

double CapacitiveBeam::capacitancePerMetre_f_per_m() const
{
    return capacitancePerNewton_f_per_n() / tipDeflectionPerNewton_m();
}

}  // namespace tactiscope::core::sensors
