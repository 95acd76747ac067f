// What one acquisition channel measures: its name, unit, physical kind and,
// when known, its role in a mode (which cantilever or beam it is). Shared
// by devices (which announce channels), processors (which pick the channels
// they need by role, core/modes/ModeDefinition.h) and the UI (which labels
// axes).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tactiscope::core {

// Decision: what a probe's own detector decided, sample by sample (its
// decision −1/0/+1 and its best R each way: docs/protocol.md), recorded as
// channels and checked against the workstation's.
enum class ChannelKind { Strain, Capacitance, Force, Position, Other, Decision };

// Stable lower-case names, used in files and on the command line.
std::string_view toString(ChannelKind kind);
std::optional<ChannelKind> channelKindFromString(std::string_view name);

// What a channel is to a mode. A device may declare it (the text
// protocol's NAME@ROLE labels), a sensor profile or the user may give it
// (the device panel, `record --roles`); a channel without one is matched
// by its kind. The texts are the command line's and the store's words.
// ReferenceForce: a force known from another instrument (a load cell),
// that a capacitive beam is calibrated against (issue 40); it may come
// from another device of the session than the beam. Position: where the
// probe is along a panel scan's stroke (an encoder or a linear
// potentiometer), which places each crossing of a dent directly (issue 55).
enum class ChannelRole {
    CantileverA,
    CantileverB,
    StiffBeam,
    SoftBeam,
    Displacement,
    Capacitance,
    ReferenceForce,
    Position
};
std::string_view toString(ChannelRole role);  // "cantilever-a", "cantilever-b", "stiff-beam", …
std::optional<ChannelRole> channelRoleFromString(std::string_view name);  // none for "" or an unknown word
std::string_view roleWord(const std::optional<ChannelRole>& role);        // "" for none, as stored
// "cantilever-a, cantilever-b, stiff-beam, soft-beam, displacement, capacitance, reference-force or position"
std::string channelRoleChoices();

struct ChannelDescriptor {
    std::string name;
    // SI unit symbol of the stored values; empty for dimensionless quantities
    // such as strain.
    std::string unit;
    ChannelKind kind = ChannelKind::Other;
    std::optional<ChannelRole> role = std::nullopt;  // none: the modes match the channel by its kind

    friend bool operator==(const ChannelDescriptor&, const ChannelDescriptor&) = default;
};

// The first name two of `channels` share, or none: a session's export
// names its columns by them, so one recorded with two channels "a" could
// not be imported back.
std::optional<std::string> repeatedChannelName(std::span<const ChannelDescriptor> channels);

}  // namespace tactiscope::core
