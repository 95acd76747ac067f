// The hum added after the scenario's own samples.
#include "devices/simulator/MainsHumOverlay.h"

#include "core/SampleBlock.h"

#include <cmath>
#include <numbers>

namespace tactiscope::devices::simulator {
namespace {

bool hums(core::ChannelKind kind)
{
    return kind == core::ChannelKind::Strain || kind == core::ChannelKind::Force ||
           kind == core::ChannelKind::Capacitance || kind == core::ChannelKind::Other;
}

}  // namespace

HummedScenario::HummedScenario(std::unique_ptr<SimulatedScenario> inner, const MainsHumSettings& hum)
    : m_inner(std::move(inner)),
      m_hum(hum)
{
}

void HummedScenario::generate(core::SampleBlock& block)
{
    m_inner->generate(block);
    const auto& channels = m_inner->channels();
    const double rate_hz = m_inner->sampleRate_hz();
    int sign = 1;
    for (std::size_t c = 0; c < block.channelCount() && c < channels.size(); ++c) {
        if (!hums(channels[c].kind)) continue;
        const double amplitude = m_hum.common + sign * m_hum.differential;
        sign = -sign;
        auto values = block.channel(c);
        for (std::size_t i = 0; i < values.size(); ++i) {
            // Samples counted here, not the block's index: an emulator's
            // load sweep takes its samples one block of one at a time.
            const double t_s = static_cast<double>(m_produced + i) / rate_hz;
            const double phase = 2.0 * std::numbers::pi * m_hum.mains_hz * t_s + m_hum.phase_rad;
            values[i] += amplitude * (std::sin(phase) + m_hum.thirdHarmonic * std::sin(3.0 * phase));
        }
    }
    m_produced += block.sampleCount();
}

}  // namespace tactiscope::devices::simulator
