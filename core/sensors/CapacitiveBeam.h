// The extra-soft capacitive force/displacement sensor of seed 002: a
// uniform-strength (triangular) cantilever with an ionic-skin capacitive
// sheet bonded to the first α·l of it.
//
// Geometry (Fig. 4, eq. 4): segment 1 (0 ≤ x ≤ α·l) is the beam with the
// sheet, width b·(l − x)/l; segment 2 (α·l ≤ x ≤ l) is bare beam of constant
// width (1 − α)·b. The triangular width keeps the curvature, and so the
// sheet's strain, the same all along segment 1 — the point of the design.
//
// In the z order of the paper the sheet's layers come first (outermost at
// z = 0) and the beam last, so the sheet/beam interface is z₃ for a
// three-layer sheet. With A_j and z_Nj of each segment's layer stack:
//   sheet strain      ε_d = (z_N1 − z_U)·F·l/(A_1·b)             (eqs 11–12)
//   capacitance       ΔC  = C0·ε_d                                (eqs 1, 13)
//   tip deflection    w(l) = F·[(2α − α²)·l³/(2A_1b) + (1 − α)²·l³/(3A_2b)]  (28)
//   stiffness         k_s = F/w(l)                                (eq. 30)
//   ΔC per deflection ΔC/w(l)                                     (eq. 31)
// SI units: F in newtons, C in farads.
#pragma once

#include "core/sensors/LayeredSection.h"

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::sensors {

struct UniformStrengthBeam {
    double length_m = 0.0;     // l
    double rootWidth_m = 0.0;  // b
    double thickness_m = 0.0;
    double youngsModulus_pa = 0.0;
    double sheetLengthRatio = 0.0;  // α, in (0, 1)
};

struct SheetLayer {
    std::string name;
    double thickness_m = 0.0;
    double youngsModulus_pa = 0.0;
};

struct CapacitiveBeamGeometry {
    UniformStrengthBeam beam;
    std::vector<SheetLayer> sheetLayers;  // from the beam surface outward
    double c0_f = 0.0;                    // undeformed capacitance
    std::optional<double> doubleLayer_f;  // C_EDL, when the series correction is wanted
};

class CapacitiveBeam {
public:
    // Throws std::invalid_argument for non-physical geometry.
    explicit CapacitiveBeam(const CapacitiveBeamGeometry& geometry);

    const CapacitiveBeamGeometry& geometry() const { return m_g; }
    const SectionProperties& segment1() const { return m_segment1; }  // sheet + beam
    const SectionProperties& segment2() const { return m_segment2; }  // beam alone
    double interface_m() const { return m_interface_m; }              // z_U

    double sheetStrainPerNewton() const;
    double capacitancePerNewton_f_per_n() const;  // eq. 13 (with the EDL correction if set)
    double tipDeflectionPerNewton_m() const;      // eq. 28
    double stiffness_n_per_m() const;             // eq. 30
    double capacitancePerMetre_f_per_m() const;   // eq. 31

private:
    CapacitiveBeamGeometry m_g;
    SectionProperties m_segment1;
    SectionProperties m_segment2;
    double m_interface_m;
};

// Measured capacitance of a dielectric C_d in series with the two electrical
// double layers of the ionic electrodes: C = C_d / (2·C_d/C_EDL + 1).
double seriesDoubleLayerCapacitance(double dielectric_f, double doubleLayer_f);

}  // namespace tactiscope::core::sensors
