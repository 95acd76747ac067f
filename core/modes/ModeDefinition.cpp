// ModeDefinition: the table of modes. A new sensor type starts here.
#include "core/modes/ModeDefinition.h"

#include <array>
#include <stdexcept>
#include <string>

namespace tactiscope::core {
namespace {

constexpr std::array kPanelScanRoles{ChannelRole::CantileverA, ChannelRole::CantileverB};
constexpr std::array kPalpationRoles{ChannelRole::StiffBeam, ChannelRole::SoftBeam, ChannelRole::Displacement};
constexpr std::array kCapacitiveRoles{ChannelRole::Capacitance};

const std::array kDefinitions{
    ModeDefinition{.mode = Mode::PanelScan,
                   .name = "panel-scan",
                   .needs = "two strain cantilevers (A and B)",
                   .roles = kPanelScanRoles,
                   .profileKind = {},
                   .detectsDefects = true,
                   .readings = std::nullopt,
                   .noZero = "panel scan has no zero to take: the detector works on the signals' changes"},
    ModeDefinition{.mode = Mode::Palpation,
                   .name = "palpation",
                   .needs = "a stiff and a soft beam and a displacement",
                   .roles = kPalpationRoles,
                   .profileKind = "a compliance pair (two beams)",
                   .detectsDefects = false,
                   .readings = ReadingKind::Compliance,
                   .noZero = {}},
    ModeDefinition{.mode = Mode::Capacitive,
                   .name = "capacitive",
                   .needs = "a capacitance",
                   .roles = kCapacitiveRoles,
                   .profileKind = "a capacitive beam",
                   .detectsDefects = false,
                   .readings = std::nullopt,
                   .noZero = {}},
    ModeDefinition{.mode = Mode::General,
                   .name = "general",
                   .needs = "any channels",
                   .roles = {},
                   .profileKind = {},
                   .detectsDefects = false,
                   .readings = std::nullopt,
                   .noZero = "general recording has no zero to take: it stores the channels as they come"},
};

}  // namespace

std::span<const ModeDefinition> modeDefinitions()
{
    return kDefinitions;
}

const ModeDefinition& definitionOf(Mode mode)
{
    for (const auto& definition : kDefinitions)
        if (definition.mode == mode) return definition;
    throw std::out_of_range("no definition for mode " + std::to_string(static_cast<int>(mode)));
}

bool kindCanPlay(ChannelKind kind, ChannelRole role)
{
    switch (role) {
    case ChannelRole::CantileverA:
    case ChannelRole::CantileverB:
        return kind == ChannelKind::Strain;
    case ChannelRole::StiffBeam:
    case ChannelRole::SoftBeam:
        return kind != ChannelKind::Position;
    case ChannelRole::Displacement:
        return kind == ChannelKind::Position;
    case ChannelRole::Capacitance:
        return kind == ChannelKind::Capacitance;
    }
    return false;
}

}  // namespace tactiscope::core
