// CapacitiveWeightsScenario: protocol schedule and beam response.
#include "devices/simulator/CapacitiveWeightsScenario.h"

#include "core/SampleBlock.h"
#include "core/calibration/CapacitiveCalibration.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::devices::simulator {

core::sensors::CapacitiveBeamGeometry CapacitiveWeightsParameters::paperSensorNo1()
{
    core::sensors::CapacitiveBeamGeometry g;
    g.beam = {0.015, 0.005, 0.002368, 83e3, 0.6};
    g.sheetLayers = {
        {"inner electrode", 0.000462, 1800.0}, {"dielectric", 0.000015, 83e3}, {"outer electrode", 0.000462, 1800.0}};
    g.c0_f = 51.44e-12;
    return g;
}

CapacitiveWeightsScenario::CapacitiveWeightsScenario(const CapacitiveWeightsParameters& p)
    : m_p(p),
      m_channels{{"capacitance", "F", core::ChannelKind::Capacitance}},
      m_beam(p.geometry),
      m_noise(p.seed * 2 + 0, p.noise_f),
      m_wanderSteps(p.seed * 2 + 1, p.wander_f_per_sqrt_s * std::sqrt(1.0 / p.sampleRate_hz))
{
    if (!(p.sampleRate_hz > 0.0) || !(p.dwell_s > 0.0) || !(p.baseline_s >= 0.0) || !(p.settleTime_s > 0.0) ||
        !(p.creepTime_s > 0.0))
        throw std::invalid_argument("capacitive weights: rates and times must be positive");
    if (p.weights_mgf.empty()) throw std::invalid_argument("capacitive weights: no weights");
    double t = p.baseline_s;
    const auto add = [&](double mgf, bool loading) {
        m_schedule.push_back({t, t + p.dwell_s, mgf * core::calibration::kMilligramForce_n, loading});
        t += p.dwell_s;
    };
    if (p.protocol == WeightProtocol::Cumulative) {
        for (double w : p.weights_mgf) add(w, true);
        for (auto it = p.weights_mgf.rbegin() + 1; it != p.weights_mgf.rend(); ++it) add(*it, false);
    } else if (p.protocol == WeightProtocol::Individual) {
        for (double w : p.weights_mgf) {
            add(w, true);
            add(0.0, false);
        }
    } else {
        m_rig = std::make_shared<LoadRig>();
    }
    m_duration_s = t + p.baseline_s;
}

double CapacitiveWeightsScenario::loadAt_n(double t_s) const
{
    if (m_rig) return m_rig->load_n();
    for (const WeightStep& step : m_schedule) {
        if (t_s >= step.start_s && t_s < step.end_s) return step.force_n;
    }
    return 0.0;
}

void CapacitiveWeightsScenario::generate(core::SampleBlock& block)
{
    const double dt = 1.0 / m_p.sampleRate_hz;
    const double settle = 1.0 - std::exp(-dt / m_p.settleTime_s);
    const double creep = 1.0 - std::exp(-dt / m_p.creepTime_s);
    const double perNewton = m_beam.capacitancePerNewton_f_per_n();
    auto c = block.channel(0);
    for (std::size_t i = 0; i < block.sampleCount(); ++i, ++m_nextSample) {
        const double t_s = static_cast<double>(m_nextSample) * dt;
        const double load = loadAt_n(t_s);
        m_settled_n += (load - m_settled_n) * settle;
        m_creep_n += (m_p.creepFraction * m_settled_n - m_creep_n) * creep;
        m_wander_f += m_wanderSteps.next();
        c[i] = m_p.geometry.c0_f + m_p.drift_f_per_s * t_s + m_wander_f + perNewton * (m_settled_n + m_creep_n) +
               m_noise.next();
    }
}

}  // namespace tactiscope::devices::simulator
