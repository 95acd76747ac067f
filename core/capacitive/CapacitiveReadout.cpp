// CapacitiveReadout: scaling and the unloaded-only drift rule.
#include "core/capacitive/CapacitiveReadout.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::capacitive {

CapacitiveSensitivity CapacitiveSensitivity::fromModel(const sensors::CapacitiveBeam& beam)
{
    return {beam.geometry().c0_f, beam.capacitancePerNewton_f_per_n(), beam.capacitancePerMetre_f_per_m()};
}

CapacitiveSensitivity CapacitiveSensitivity::fromCalibration(const calibration::CapacitiveCalibrationResult& c,
                                                             const sensors::CapacitiveBeam& beam)
{
    const double k = beam.stiffness_n_per_m();
    CapacitiveSensitivity s{c.c0_f, 0.0, 0.0};
    if (c.forceFit) s.perNewton_f = c.forceFit->slope;
    if (c.displacementFit) s.perMetre_f = c.displacementFit->slope;
    // ΔC/w = (ΔC/F)·k_s: fill the one not calibrated from the other.
    if (!c.displacementFit) s.perMetre_f = s.perNewton_f * k;
    if (!c.forceFit) s.perNewton_f = s.perMetre_f / k;
    return s;
}

CapacitiveReadout::CapacitiveReadout(const CapacitiveSensitivity& sensitivity, const DriftSettings& drift)
    : m_sensitivity(sensitivity),
      m_drift(drift),
      m_c0_f(sensitivity.c0_f),
      m_tracked_f(sensitivity.c0_f)
{
    if (!(sensitivity.c0_f > 0.0) || !(sensitivity.perNewton_f > 0.0) || !(sensitivity.perMetre_f > 0.0))
        throw std::invalid_argument("capacitive readout needs positive C0 and sensitivities");
    if (!(drift.timeConstant_s > 0.0)) throw std::invalid_argument("drift time constant must be positive");
}

void CapacitiveReadout::tare()
{
    if (m_last_s) setBaseline(m_smoothed_f);
}

void CapacitiveReadout::setBaseline(double c0_f)
{
    m_c0_f = m_tracked_f = c0_f;
    ++m_baselineChanges;
}

CapacitiveReading CapacitiveReadout::readingAt(double t_s, double c_f, double c0_f,
                                               const CapacitiveSensitivity& sensitivity)
{
    CapacitiveReading r;
    r.t_s = t_s;
    r.capacitance_f = c_f;
    r.c0_f = c0_f;
    r.deltaC_f = c_f - c0_f;
    r.relativeChange = r.deltaC_f / c0_f;
    r.force_n = r.deltaC_f / sensitivity.perNewton_f;
    r.displacement_m = r.deltaC_f / sensitivity.perMetre_f;
    return r;
}

CapacitiveReading CapacitiveReadout::push(double t_s, double c_f)
{
    const double dt = m_last_s ? t_s - *m_last_s : 0.0;
    m_smoothed_f = m_last_s ? m_smoothed_f + (c_f - m_smoothed_f) * (1.0 - std::exp(-dt / 0.5)) : c_f;
    m_last_s = t_s;

    bool unloaded = false;
    if (m_drift.noiseSigma_f > 0.0) {
        const bool quiet = std::abs(c_f - m_c0_f) <= m_drift.quietBand_sigmas * m_drift.noiseSigma_f;
        if (quiet && !m_quiet) m_quietSince_s = t_s;
        m_quiet = quiet;
        unloaded = quiet && t_s - m_quietSince_s >= m_drift.quietFor_s;
        if (unloaded) {
            m_tracked_f += (c_f - m_tracked_f) * (1.0 - std::exp(-dt / m_drift.timeConstant_s));
            if (std::abs(m_tracked_f - m_c0_f) > kStep_sigmas * m_drift.noiseSigma_f) {
                m_c0_f = m_tracked_f;
                ++m_baselineChanges;
            }
        }
    }

    CapacitiveReading r = readingAt(t_s, c_f, m_c0_f, m_sensitivity);
    r.unloaded = unloaded;
    return r;
}

}  // namespace tactiscope::core::capacitive
