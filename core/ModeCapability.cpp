// ModeCapability: each mode's channel needs and the sentence that names them.
#include "core/ModeCapability.h"

namespace tactiscope::core {
namespace {

std::vector<std::size_t> channelsOfKind(std::span<const ChannelDescriptor> channels, ChannelKind kind, bool wanted)
{
    std::vector<std::size_t> found;
    for (std::size_t c = 0; c < channels.size(); ++c)
        if ((channels[c].kind == kind) == wanted) found.push_back(c);
    return found;
}

std::string needs(Mode mode)
{
    switch (mode) {
    case Mode::PanelScan:
        return "two strain channels (cantilevers A and B)";
    case Mode::Palpation:
        return "two beam channels and a displacement (position) channel";
    case Mode::Capacitive:
        return "a capacitance channel";
    }
    return {};
}

std::string described(std::span<const ChannelDescriptor> channels)
{
    if (channels.empty()) return "none";
    std::string text;
    for (const auto& channel : channels) {
        if (!text.empty()) text += ", ";
        text += channel.name + " (" + std::string(toString(channel.kind)) + ")";
    }
    return text;
}

}  // namespace

std::optional<std::vector<std::size_t>> modeChannels(Mode mode, std::span<const ChannelDescriptor> channels)
{
    switch (mode) {
    case Mode::PanelScan: {
        auto strain = channelsOfKind(channels, ChannelKind::Strain, true);
        if (strain.size() < 2) return std::nullopt;
        strain.resize(2);
        return strain;
    }
    case Mode::Palpation: {
        const auto positions = channelsOfKind(channels, ChannelKind::Position, true);
        auto beams = channelsOfKind(channels, ChannelKind::Position, false);
        if (positions.empty() || beams.size() < 2) return std::nullopt;
        beams.resize(2);
        beams.push_back(positions.front());
        return beams;
    }
    case Mode::Capacitive: {
        const auto capacitance = channelsOfKind(channels, ChannelKind::Capacitance, true);
        if (capacitance.empty()) return std::nullopt;
        return std::vector<std::size_t>{capacitance.front()};
    }
    }
    return std::nullopt;
}

std::optional<std::string> modeRefusal(Mode mode, std::span<const ChannelDescriptor> channels)
{
    if (modeChannels(mode, channels)) return std::nullopt;
    return std::string(toString(mode)) + " needs " + needs(mode) + "; this device has " + described(channels) + ".";
}

std::vector<Mode> runnableModes(std::span<const ChannelDescriptor> channels)
{
    std::vector<Mode> modes;
    for (const Mode mode : kModes)
        if (modeChannels(mode, channels)) modes.push_back(mode);
    return modes;
}

}  // namespace tactiscope::core
