// ModeRegistry: the list of modes every layer asks. A new sensor type adds
// its definition here (or registers it) and its file beside this one.
#include "core/modes/ModeDefinition.h"

#include "core/UnitScale.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace tactiscope::core {
namespace {

std::vector<ModeDefinition>& registry()
{
    static std::vector<ModeDefinition> modes{panelScanMode(), palpationMode(), capacitiveMode(), generalMode()};
    return modes;
}

// The built-in modes, first in the registry, never taken out.
constexpr std::size_t kBuiltIn = 4;

}  // namespace

std::span<const ModeDefinition> modeDefinitions()
{
    return registry();
}

const ModeDefinition& definitionOf(Mode mode)
{
    for (const auto& definition : registry())
        if (definition.mode == mode) return definition;
    throw std::out_of_range("no definition for mode " + std::to_string(static_cast<int>(mode)));
}

void registerMode(const ModeDefinition& definition)
{
    for (const auto& known : registry())
        if (known.mode == definition.mode || known.name == definition.name)
            throw std::invalid_argument("the mode '" + std::string(definition.name) + "' is already defined");
    registry().push_back(definition);
}

void unregisterMode(Mode mode)
{
    auto& modes = registry();
    const auto found = std::ranges::find(modes.begin() + kBuiltIn, modes.end(), mode, &ModeDefinition::mode);
    if (found != modes.end()) modes.erase(found);
}

bool canPlay(const ChannelDescriptor& channel, ChannelRole role)
{
    const ChannelKind kind = channel.kind;
    switch (role) {
    case ChannelRole::CantileverA:
    case ChannelRole::CantileverB:
        return kind == ChannelKind::Strain;
    case ChannelRole::StiffBeam:
    case ChannelRole::SoftBeam:
        return kind == ChannelKind::Strain || kind == ChannelKind::Force || isCounts(channel.unit);
    case ChannelRole::Displacement:
        return kind == ChannelKind::Position || isCounts(channel.unit);
    case ChannelRole::Capacitance:
        // Counts only when given the role (a capacitive profile's scale
        // gives it): a strain probe's counts are no capacitance.
        return kind == ChannelKind::Capacitance || (isCounts(channel.unit) && channel.role == role);
    case ChannelRole::ReferenceForce:
        return kind == ChannelKind::Force;
    case ChannelRole::Position:
        return kind == ChannelKind::Position;
    }
    return false;
}

std::string_view quantityFor(ChannelRole role)
{
    switch (role) {
    case ChannelRole::CantileverA:
    case ChannelRole::CantileverB:
        return "a strain (strain, µε)";
    case ChannelRole::StiffBeam:
    case ChannelRole::SoftBeam:
        return "a strain (strain, µε), a force (N, mN) or ADC counts with their scale";
    case ChannelRole::Displacement:
        return "a length (m, mm) or counts with their scale";
    case ChannelRole::Capacitance:
        return "a capacitance (F, pF) or counts with their scale";
    case ChannelRole::ReferenceForce:
        return "a force (N, mN)";
    case ChannelRole::Position:
        return "a length (m, mm)";
    }
    return "";
}

}  // namespace tactiscope::core
