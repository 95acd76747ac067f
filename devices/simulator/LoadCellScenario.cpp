// LoadCellScenario: the rig's load, the cell's zero and its noise.
#include "devices/simulator/LoadCellScenario.h"

#include "core/SampleBlock.h"

#include <stdexcept>

namespace tactiscope::devices::simulator {

LoadCellScenario::LoadCellScenario(const LoadCellParameters& p)
    : m_p(p),
      m_channels{{"force", "N", core::ChannelKind::Force}},
      m_noise(p.seed * 2 + 0, p.noise_n)
{
    if (!(p.sampleRate_hz > 0.0) || !(p.noise_n >= 0.0))
        throw std::invalid_argument("load cell: the rate must be positive and the noise not negative");
}

void LoadCellScenario::generate(core::SampleBlock& block)
{
    auto force = block.channel(0);
    for (double& value : force) value = m_rig->load_n() + m_p.zero_n + m_noise.next();
}

}  // namespace tactiscope::devices::simulator
