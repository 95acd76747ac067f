// GaugeCalibrationScenario: rig load → lagged tip force → root strain → counts.
#include "devices/simulator/GaugeCalibrationScenario.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::devices::simulator {
namespace {

core::straingauge::StrainGaugeChain trueChain(const GaugeCalibrationParameters& p)
{
    if (!(p.trueGaugeFactor > 0.0)) throw std::invalid_argument("gauge calibration: gauge factor must be positive");
    core::straingauge::BridgeSettings bridge = p.bridge;
    bridge.gaugeFactor = p.trueGaugeFactor;
    return {p.adc, bridge};
}

}  // namespace

GaugeCalibrationScenario::GaugeCalibrationScenario(const GaugeCalibrationParameters& parameters)
    : m_p(parameters),
      m_channels{{parameters.softBeam ? "low" : "high", "count", core::ChannelKind::Other,
                  parameters.softBeam ? core::ChannelRole::SoftBeam : core::ChannelRole::StiffBeam}},
      m_beam(parameters.softBeam ? kProbeSoftBeam : parameters.beam),
      m_trueChain(trueChain(parameters)),
      m_noise(parameters.seed, parameters.electricalNoise_v)
{
    if (!(m_p.sampleRate_hz > 0.0) || !(m_p.settleTime_s > 0.0))
        throw std::invalid_argument("gauge calibration: rate and settling time must be positive");
}

void GaugeCalibrationScenario::generate(core::SampleBlock& block)
{
    const double settle = 1.0 - std::exp(-1.0 / (m_p.sampleRate_hz * m_p.settleTime_s));
    const double fullScale = m_trueChain.fullScaleCounts();
    const double noiseScale = fullScale / m_p.adc.reference_v;
    auto counts = block.channel(0);
    for (double& value : counts) {
        m_settled_n += (m_rig->load_n() - m_settled_n) * settle;
        const double ideal =
            m_trueChain.countsForStrain(m_settled_n * m_beam.rootStrainPerNewton(), m_p.zeroOffset_counts);
        value = std::clamp(std::round(ideal + m_noise.next() * noiseScale), -fullScale, fullScale - 1.0);
    }
}

}  // namespace tactiscope::devices::simulator
