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
        if (channels[c].role == role) return canPlay(channels[c], role) ? c : kNone;
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (!channels[c].role && canPlay(channels[c], role) && std::ranges::find(taken, c) == taken.end()) return c;
    return kNone;
}

// "a plain number", "in °C": what a channel's values are, for a refusal.
std::string valuesOf(const ChannelDescriptor& channel)
{
    if (channel.kind != ChannelKind::Other) return "a " + std::string(toString(channel.kind));
    return channel.unit.empty() ? "a plain number (no unit)" : "in " + channel.unit;
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
    std::string missing, unfit;
    for (std::size_t r = 0; r < picked.size(); ++r) {
        if (picked[r] != kNone) continue;
        const ChannelRole role = definition.roles[r];
        // Given the role, but its values are not what the role reads: the
        // unit (or the scale) is what is missing, not a channel.
        const auto given = std::ranges::find(channels, std::optional(role), &ChannelDescriptor::role);
        if (given != channels.end()) {
            unfit += (unfit.empty() ? "" : "; ") + given->name + " plays " + std::string(toString(role)) + " but is " +
                     valuesOf(*given) + ", and " + std::string(toString(role)) + " reads " +
                     std::string(quantityFor(role));
            continue;
        }
        if (!missing.empty()) missing += ", ";
        missing += toString(role);
    }
    if (missing.empty() && unfit.empty()) return std::nullopt;
    std::string text = std::string(definition.name) + " needs " + std::string(definition.needs) + ": ";
    if (!unfit.empty()) text += unfit + (missing.empty() ? "" : "; ");
    if (!missing.empty()) text += "no channel plays " + missing;
    return text + "; this device has " + described(channels) + ".";
}

std::vector<std::string> channelsWithoutFittingUnit(Mode mode, std::span<const ChannelDescriptor> channels)
{
    std::vector<std::string> names;
    for (const ChannelRole role : definitionOf(mode).roles)
        for (const auto& channel : channels)
            if (channel.role == role && !canPlay(channel, role)) names.push_back(channel.name);
    return names;
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
