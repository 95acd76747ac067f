// ShuntedBridges: the Wheatstone bridge from its resistances, read back as
// a probe's firmware does.
#include "devices/simulator/ShuntedBridges.h"

namespace tactiscope::devices::simulator {
namespace {

double bridgeRatio(double r1, double r2, double r3, double r4)
{
    return r1 / (r1 + r2) - r4 / (r3 + r4);
}

}  // namespace

double shuntedReading(const ProbeBridge& b)
{
    const double rg = b.gauge_ohm;
    const double shunted = rg * b.shunt_ohm / (rg + b.shunt_ohm);
    const double vr = bridgeRatio(shunted, rg, rg, rg) - bridgeRatio(rg, rg, rg, rg);
    using core::straingauge::BridgeType;
    switch (b.type) {
    case BridgeType::Quarter:
        return 4.0 * vr / (b.gaugeFactor * (1.0 - 2.0 * vr));
    case BridgeType::HalfBending:
        return 2.0 * vr / b.gaugeFactor;
    case BridgeType::FullBending:
        return vr / b.gaugeFactor;
    }
    return 0.0;
}

ShuntedBridges::ShuntedBridges(std::vector<core::ChannelDescriptor> channels, ProbeBridge bridge)
    : m_channels(std::move(channels)),
      m_on(m_channels.size(), false),
      m_step(shuntedReading(bridge))
{
}

std::optional<std::string> ShuntedBridges::set(std::size_t channel, bool on)
{
    if (channel >= m_channels.size()) return "there is no channel " + std::to_string(channel + 1);
    if (m_channels[channel].kind != core::ChannelKind::Strain)
        return "channel " + m_channels[channel].name + " has no bridge to shunt";
    m_on[channel] = on;
    return std::nullopt;
}

void ShuntedBridges::apply(core::SampleBlock& block) const
{
    for (std::size_t c = 0; c < block.channelCount() && c < m_on.size(); ++c)
        if (m_on[c])
            for (double& value : block.channel(c)) value += m_step;
}

}  // namespace tactiscope::devices::simulator
