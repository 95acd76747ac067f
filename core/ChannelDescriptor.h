// What one acquisition channel measures: its name, unit and physical kind.
// Shared by devices (which announce channels), processors (which pick the
// channels they need by kind) and the UI (which labels axes).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core {

enum class ChannelKind { Strain, Capacitance, Force, Position, Other };

// Stable lower-case names, used in files and on the command line.
std::string_view toString(ChannelKind kind);
std::optional<ChannelKind> channelKindFromString(std::string_view name);

struct ChannelDescriptor {
    std::string name;
    // SI unit symbol of the stored values; empty for dimensionless quantities
    // such as strain.
    std::string unit;
    ChannelKind kind = ChannelKind::Other;

    friend bool operator==(const ChannelDescriptor&, const ChannelDescriptor&) = default;
};

}  // namespace tactiscope::core
