// ModeCapability: matching a mode's roles to a device's channels, and the
// sentence that names what is missing.
#include "core/ModeCapability.h"

#include "core/modes/ModeDefinition.h"

#include <algorithm>

namespace tactiscope::core {
namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

std::size_t channelFor(ChannelRole role, std::span<const ChannelDescriptor> channels,
                       std::span<const std::size_t> taken)
{
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c].role == role) return c;
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (!channels[c].role && kindCanPlay(channels[c].kind, role) && std::ranges::find(taken, c) == taken.end())
            return c;
    return kNone;
}

// The channel each role of `mode` goes to (kNone where none can).
std::vector<std::size_t> roleChannels(Mode mode, std::span<const ChannelDescriptor> channels)
{
    std::vector<std::size_t> picked;
    for (const ChannelRole role : definitionOf(mode).roles) picked.push_back(channelFor(role, channels, picked));
    return picked;
}

std::string described(std::span<const ChannelDescriptor> channels)
{
    if (channels.empty()) return "none";
    std::string text;
    for (const auto& channel : channels) {
        if (!text.empty()) text += ", ";
        text +=
            channel.name + " (" + std::string(channel.role ? toString(*channel.role) : toString(channel.kind)) + ")";
    }
    return text;
}

}  // namespace

std::optional<std::vector<std::size_t>> modeChannels(Mode mode, std::span<const ChannelDescriptor> channels)
{
    auto picked = roleChannels(mode, channels);
    if (std::ranges::find(picked, kNone) != picked.end()) return std::nullopt;
    return picked;
}

std::optional<std::string> modeRefusal(Mode mode, std::span<const ChannelDescriptor> channels)
{
    const auto& definition = definitionOf(mode);
    const auto picked = roleChannels(mode, channels);
    std::string missing;
    for (std::size_t r = 0; r < picked.size(); ++r) {
        if (picked[r] != kNone) continue;
        if (!missing.empty()) missing += ", ";
        missing += toString(definition.roles[r]);
    }
    if (missing.empty()) return std::nullopt;
    return std::string(definition.name) + " needs " + std::string(definition.needs) + ": no channel plays " + missing +
           "; this device has " + described(channels) + ".";
}

std::string roleExample(Mode mode, std::span<const ChannelDescriptor> channels)
{
    const auto roles = definitionOf(mode).roles;
    std::string example;
    for (std::size_t r = 0; r < roles.size(); ++r) {
        if (!example.empty()) example += ",";
        example += (r < channels.size() ? channels[r].name : "NAME") + "=" + std::string(toString(roles[r]));
    }
    return example;
}

std::vector<Mode> runnableModes(std::span<const ChannelDescriptor> channels)
{
    std::vector<Mode> modes;
    for (const auto& definition : modeDefinitions())
        if (modeChannels(definition.mode, channels)) modes.push_back(definition.mode);
    return modes;
}

}  // namespace tactiscope::core
