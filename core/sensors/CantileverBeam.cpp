// Euler–Bernoulli formulas for the end-loaded cantilever.
#include "core/sensors/CantileverBeam.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tactiscope::core::sensors {

CantileverBeam::CantileverBeam(const CantileverGeometry& g)
    : m_g(g)
{
    const auto check = [](double value, const char* what) {
        if (!(std::isfinite(value) && value > 0.0))
            throw std::invalid_argument(std::string("cantilever ") + what + " must be positive");
    };
    check(g.length_m, "length");
    check(g.width_m, "width");
    check(g.thickness_m, "thickness");
    check(g.youngsModulus_pa, "Young's modulus");
}

double CantileverBeam::stiffness_n_per_m() const
{
    const double t = m_g.thickness_m;
    const double L = m_g.length_m;
    return m_g.youngsModulus_pa * m_g.width_m * t * t * t / (4.0 * L * L * L);
}

double CantileverBeam::rootStrainPerNewton() const
{
    const double t = m_g.thickness_m;
    return 6.0 * m_g.length_m / (m_g.youngsModulus_pa * m_g.width_m * t * t);
}

double CantileverBeam::tipDeflectionPerNewton_m() const
{
    return 1.0 / stiffness_n_per_m();
}

}  // namespace tactiscope::core::sensors
