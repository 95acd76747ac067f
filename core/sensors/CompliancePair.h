// Two cantilevers of different stiffness pressed together on an object
// (seed 001, section 2.2): each side is the beam in series with the object,
// and both sides see the same far-field displacement, so the force ratio
//   Q = F_H/F_L = k_h·(k_o + k_l) / (k_l·(k_o + k_h))            (eq. 1)
// does not depend on how far the probe is pressed, and inverts to
//   k_o = k_h·k_l·(1 − Q) / (Q·k_l − k_h).                       (eq. 2)
// Q runs from 1 (k_o → 0) to k_h/k_l (k_o → ∞); outside (1, k_h/k_l) there is
// no stiffness to report, and this class says so instead of returning a
// negative or infinite number. Q within rounding (8 ulp) of either end is
// out of range too: there k_o is a quotient of rounding errors.
#pragma once

#include "core/sensors/CantileverBeam.h"

#include <cstddef>
#include <vector>

namespace tactiscope::core::sensors {

enum class ComplianceRange {
    Below,    // Q ≤ 1 (within rounding): softer than the probe can tell from nothing
    InRange,  // 1 < Q < k_h/k_l
    Above,    // Q ≥ k_h/k_l (within rounding): stiffer than the probe can resolve
};

struct StiffnessReading {
    ComplianceRange range = ComplianceRange::Below;
    double objectStiffness_n_per_m = 0.0;  // only meaningful when InRange
};

// How the pair behaves on an object of stiffness k_o (section 2.2.3, Figs 5–7).
struct DesignPoint {
    double objectStiffness_n_per_m = 0.0;
    double q = 0.0;                // F_H/F_L
    double dqDk_m_per_n = 0.0;     // dQ/dk_o
    double strainRatio = 0.0;      // ε_l/ε_h at the roots
    double deflectionRatio = 0.0;  // Δ_l/Δ_h at the tips
    // Per metre of probe displacement into the object:
    double strainHigh_per_m = 0.0;
    double strainLow_per_m = 0.0;
    double deflectionHigh = 0.0;  // m of tip deflection per m pressed
    double deflectionLow = 0.0;
};

class CompliancePair {
public:
    // Throws std::invalid_argument unless the high beam is the stiffer one.
    CompliancePair(const CantileverBeam& high, const CantileverBeam& low);

    const CantileverBeam& high() const { return m_high; }
    const CantileverBeam& low() const { return m_low; }
    double kHigh_n_per_m() const { return m_kh; }
    double kLow_n_per_m() const { return m_kl; }
    double qMax() const { return m_kh / m_kl; }

    // Q for an object of stiffness k_o ≥ 0 (eq. 1).
    double forceRatio(double objectStiffness_n_per_m) const;
    // k_o from Q (eq. 2), with the out-of-range states.
    StiffnessReading objectStiffness(double q) const;
    // dQ/dk_o = k_h·(k_h − k_l) / (k_l·(k_o + k_h)²)  (eq. 5)
    double sensitivity_m_per_n(double objectStiffness_n_per_m) const;

    DesignPoint designPoint(double objectStiffness_n_per_m) const;
    // Design points at `count` stiffnesses evenly spaced over [from, to].
    std::vector<DesignPoint> designCurve(double from_n_per_m, double to_n_per_m, std::size_t count) const;
    // The same pair with both beams of another length (the paper compares
    // 40, 50 and 60 mm).
    CompliancePair withLength(double length_m) const;

private:
    CantileverBeam m_high;
    CantileverBeam m_low;
    double m_kh;
    double m_kl;
};

}  // namespace tactiscope::core::sensors
