// Force ratio, its inverse and the design quantities of the two-beam probe.
#include "core/sensors/CompliancePair.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tactiscope::core::sensors {

CompliancePair::CompliancePair(const CantileverBeam& high, const CantileverBeam& low)
    : m_high(high),
      m_low(low),
      m_kh(high.stiffness_n_per_m()),
      m_kl(low.stiffness_n_per_m())
{
    if (!(m_kh > m_kl)) throw std::invalid_argument("the high-stiffness beam must be stiffer than the low one");
}

double CompliancePair::forceRatio(double k_o) const
{
    if (!(k_o >= 0.0)) throw std::invalid_argument("object stiffness must not be negative");
    if (std::isinf(k_o)) return qMax();
    return m_kh * (k_o + m_kl) / (m_kl * (k_o + m_kh));
}

StiffnessReading CompliancePair::objectStiffness(double q) const
{
    // The ends of the range within rounding: k_h/k_l of the paper's probe
    // computes as 27.000000000000004, and Q = 27 typed or measured would
    // otherwise give k_o ≈ 10¹⁹ N/m from a denominator of rounding error.
    constexpr double kRounding = 8.0 * std::numeric_limits<double>::epsilon();
    if (!(q > 1.0 + kRounding)) return {ComplianceRange::Below, 0.0};  // also NaN
    if (q >= qMax() * (1.0 - kRounding)) return {ComplianceRange::Above, 0.0};
    return {ComplianceRange::InRange, m_kh * m_kl * (1.0 - q) / (q * m_kl - m_kh)};
}

double CompliancePair::sensitivity_m_per_n(double k_o) const
{
    const double s = k_o + m_kh;
    return m_kh * (m_kh - m_kl) / (m_kl * s * s);
}

DesignPoint CompliancePair::designPoint(double k_o) const
{
    DesignPoint p;
    p.objectStiffness_n_per_m = k_o;
    p.q = forceRatio(k_o);
    p.dqDk_m_per_n = sensitivity_m_per_n(k_o);
    // ε = F·(ε/F) and Δ = F/k, with F_H/F_L = Q.
    p.strainRatio = m_low.rootStrainPerNewton() / (p.q * m_high.rootStrainPerNewton());
    p.deflectionRatio = m_kh / (p.q * m_kl);
    // Pressed by X, each side is its beam in series with the object:
    // F = X·k·k_o/(k + k_o), so Δ_tip = F/k = X·k_o/(k + k_o).
    const double fHigh = m_kh * k_o / (m_kh + k_o);
    const double fLow = m_kl * k_o / (m_kl + k_o);
    p.strainHigh_per_m = fHigh * m_high.rootStrainPerNewton();
    p.strainLow_per_m = fLow * m_low.rootStrainPerNewton();
    p.deflectionHigh = fHigh / m_kh;
    p.deflectionLow = fLow / m_kl;
    return p;
}

std::vector<DesignPoint> CompliancePair::designCurve(double from, double to, std::size_t count) const
{
    if (count < 2 || !(from >= 0.0) || !(to > from))
        throw std::invalid_argument("design curve needs 0 ≤ from < to, count ≥ 2");
    std::vector<DesignPoint> curve;
    for (std::size_t i = 0; i < count; ++i)
        curve.push_back(designPoint(from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1)));
    return curve;
}

CompliancePair CompliancePair::withLength(double length_m) const
{
    CantileverGeometry high = m_high.geometry();
    CantileverGeometry low = m_low.geometry();
    high.length_m = length_m;
    low.length_m = length_m;
    return CompliancePair(CantileverBeam(high), CantileverBeam(low));
}

}  // namespace tactiscope::core::sensors
