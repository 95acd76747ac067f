// Name table for ChannelKind.
#include "core/ChannelDescriptor.h"

#include <array>
#include <utility>

namespace tactiscope::core {
namespace {

constexpr std::array<std::pair<ChannelKind, std::string_view>, 5> kKindNames{{
    {ChannelKind::Strain, "strain"},
    {ChannelKind::Capacitance, "capacitance"},
    {ChannelKind::Force, "force"},
    {ChannelKind::Position, "position"},
    {ChannelKind::Other, "other"},
}};

}  // namespace

std::string_view toString(ChannelKind kind)
{
    for (const auto& [k, name] : kKindNames) {
        if (k == kind) return name;
    }
    return "other";
}

std::optional<ChannelKind> channelKindFromString(std::string_view name)
{
    for (const auto& [k, n] : kKindNames) {
        if (n == name) return k;
    }
    return std::nullopt;
}

}  // namespace tactiscope::core
