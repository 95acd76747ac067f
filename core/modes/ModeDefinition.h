// A mode as one unit: what each layer asks about a sensor type instead of
// switching on it. One definition per mode names its record word, the
// channel roles its processor reads (in that order), the profile it takes,
// what its analysis stores, and whether it has a zero to take. The
// definitions are the table in ModeDefinition.cpp; the live processors,
// views and commands of a mode are found through them (docs/conventions.md,
// "A new mode"). Like sigrok's decoders declaring their channels, a mode
// declares roles, and any device whose channels can play them feeds it.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"

#include <optional>
#include <span>
#include <string_view>

namespace tactiscope::core {

struct ModeDefinition {
    Mode mode;
    std::string_view name;  // the record's word: "panel-scan"
    // What its channels are, for the sentence that refuses a device:
    // "two strain cantilevers (A and B)".
    std::string_view needs;
    std::span<const ChannelRole> roles;  // in the order its processor reads them
    // The kind of sensor profile it takes ("a compliance pair"); empty for
    // a mode that takes none.
    std::string_view profileKind;
    // Stores the detector's defects and decides the automatic verdict.
    bool detectsDefects = false;
    // What its analysis stores as readings, if anything.
    std::optional<ReadingKind> readings;
    // Why it has no zero to take; empty when it has one (core/ZeroRule.h).
    std::string_view noZero;
};

// Every mode, in kModes order.
std::span<const ModeDefinition> modeDefinitions();
const ModeDefinition& definitionOf(Mode mode);

// Whether a channel that was given no role can play `role` by its kind:
// cantilevers are strain channels, the palpation beams any channel but a
// position, the displacement a position, the capacitance a capacitance.
bool kindCanPlay(ChannelKind kind, ChannelRole role);

}  // namespace tactiscope::core
