// An end-loaded rectangular cantilever (seed 001, eqs 3–4, 6–7, 9–10): its
// stiffness, the surface strain at the clamped root and the tip deflection,
// each per newton of tip force. SI units throughout.
//
// Root strain is 6·F·L/(E·w·t²): the paper's eq. 6 prints L³, which is not
// even dimensionless (eq. 7, for the other beam, has it right).
#pragma once

namespace tactiscope::core::sensors {

struct CantileverGeometry {
    double length_m = 0.0;
    double width_m = 0.0;
    double thickness_m = 0.0;
    double youngsModulus_pa = 0.0;

    friend bool operator==(const CantileverGeometry&, const CantileverGeometry&) = default;
};

class CantileverBeam {
public:
    // Throws std::invalid_argument unless every dimension is a positive number.
    explicit CantileverBeam(const CantileverGeometry& geometry);

    const CantileverGeometry& geometry() const { return m_g; }

    // k = E·w·t³ / (4·L³)
    double stiffness_n_per_m() const;
    // ε_root / F = 6·L / (E·w·t²)
    double rootStrainPerNewton() const;
    // Δ_tip / F = 4·L³ / (E·w·t³) = 1/k
    double tipDeflectionPerNewton_m() const;

private:
    CantileverGeometry m_g;
};

}  // namespace tactiscope::core::sensors
