// PanelScanScenario: kinematics, surface and capsule model of a panel scan.
#include "devices/simulator/PanelScanScenario.h"

#include "core/SampleBlock.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tactiscope::devices::simulator {
namespace {

void requirePositive(double value, const char* what)
{
    if (!(std::isfinite(value) && value > 0.0))
        throw std::invalid_argument(std::string("panel scan: ") + what + " must be positive");
}

}  // namespace

PanelScanScenario::PanelScanScenario(const PanelScanParameters& parameters)
    : m_p(parameters),
      m_channels{{"a", "", core::ChannelKind::Strain}, {"b", "", core::ChannelKind::Strain}},
      // Distinct streams for the two gauges, both fixed by the one seed.
      m_noiseA(parameters.seed * 2 + 0, parameters.noiseSigma),
      m_noiseB(parameters.seed * 2 + 1, parameters.noiseSigma),
      m_decay(0.0)
{
    requirePositive(m_p.sampleRate_hz, "sample rate");
    if (!(m_p.strokeAmplitude_m >= 0.0))  // 0: the probe at rest
        throw std::invalid_argument("panel scan: stroke amplitude must not be negative");
    requirePositive(m_p.strokeFrequency_hz, "stroke frequency");
    requirePositive(m_p.defectWidth_m, "defect width");
    requirePositive(m_p.adaptationTime_s, "adaptation time");
    if (!(m_p.cantileverSpacing_m >= 0.0)) throw std::invalid_argument("panel scan: spacing must not be negative");
    if (!(m_p.noiseSigma >= 0.0)) throw std::invalid_argument("panel scan: noise must not be negative");
    m_decay = std::exp(-1.0 / (m_p.sampleRate_hz * m_p.adaptationTime_s));
    if (m_p.positionChannel) m_channels.push_back({"x", "m", core::ChannelKind::Position, core::ChannelRole::Position});
    // Start in equilibrium so there is no switch-on transient.
    m_lastInclinationA = inclination_rad(probePosition_m(0.0));
    m_lastInclinationB = inclination_rad(probePosition_m(0.0) - m_p.cantileverSpacing_m);
}

double PanelScanScenario::probePosition_m(double t_s) const
{
    const double omega = 2.0 * std::numbers::pi * m_p.strokeFrequency_hz;
    if (m_p.restBetweenPanels_s <= 0.0) return m_p.strokeAmplitude_m * std::sin(omega * t_s);
    const double stroke_s = 1.0 / m_p.strokeFrequency_hz;
    const double phase_s = std::fmod(t_s, stroke_s + m_p.restBetweenPanels_s);
    return -m_p.strokeAmplitude_m * (phase_s < stroke_s ? std::cos(omega * phase_s) : 1.0);
}

double PanelScanScenario::probeAcceleration_m_s2(double t_s) const
{
    const double omega = 2.0 * std::numbers::pi * m_p.strokeFrequency_hz;
    // Both motions are harmonic, x'' = −ω²x, while the probe moves; at rest it has none.
    if (m_p.restBetweenPanels_s > 0.0 &&
        std::fmod(t_s, 1.0 / m_p.strokeFrequency_hz + m_p.restBetweenPanels_s) >= 1.0 / m_p.strokeFrequency_hz)
        return 0.0;
    return -omega * omega * probePosition_m(t_s);
}

double PanelScanScenario::inclination_rad(double x_m) const
{
    if (!m_p.hasDefect) return 0.0;
    // Surface height h(x) = −D·exp(−u²/2) with u = (x − x_d)/σ; slope dh/dx.
    const auto slope = [&](double dent_m) {
        const double u = (x_m - dent_m) / m_p.defectWidth_m;
        return m_p.defectDepth_m / m_p.defectWidth_m * u * std::exp(-0.5 * u * u);
    };
    double inclination = slope(m_p.defectPosition_m);
    for (const double dent_m : m_p.moreDefects_m) inclination += slope(dent_m);
    return inclination;
}

void PanelScanScenario::generate(core::SampleBlock& block)
{
    const double bSign = m_p.faceToFace ? -1.0 : 1.0;
    auto a = block.channel(0);
    auto b = block.channel(1);
    for (std::size_t i = 0; i < block.sampleCount(); ++i, ++m_nextSample) {
        const double t_s = static_cast<double>(m_nextSample) / m_p.sampleRate_hz;
        const double xA = probePosition_m(t_s);
        const double xB = xA - m_p.cantileverSpacing_m;
        const double acceleration = probeAcceleration_m_s2(t_s);

        const double inclinationA = inclination_rad(xA);
        const double inclinationB = inclination_rad(xB);
        // First-order high-pass of the inclination (exact for a step per sample).
        m_bendA = m_decay * m_bendA + m_p.strainPerRadian * (inclinationA - m_lastInclinationA);
        m_bendB = m_decay * m_bendB + m_p.strainPerRadian * (inclinationB - m_lastInclinationB);
        m_lastInclinationA = inclinationA;
        m_lastInclinationB = inclinationB;

        const double inertia = m_p.strainPerAcceleration_s2_per_m * acceleration;
        a[i] = m_bendA + inertia + m_noiseA.next();
        b[i] = bSign * (m_bendB + inertia + m_noiseB.next());
        if (m_p.positionChannel) block.channel(2)[i] = xA - 0.5 * m_p.cantileverSpacing_m;
    }
}

}  // namespace tactiscope::devices::simulator
