// Name tables for ChannelKind and ChannelRole.
#include "core/ChannelDescriptor.h"

#include <array>
#include <set>
#include <string>
#include <utility>

namespace tactiscope::core {
namespace {

constexpr std::array<std::pair<ChannelKind, std::string_view>, 6> kKindNames{{
    {ChannelKind::Strain, "strain"},
    {ChannelKind::Capacitance, "capacitance"},
    {ChannelKind::Force, "force"},
    {ChannelKind::Position, "position"},
    {ChannelKind::Other, "other"},
    {ChannelKind::Decision, "decision"},
}};

constexpr std::array<std::pair<ChannelRole, std::string_view>, 8> kRoleNames{{
    {ChannelRole::CantileverA, "cantilever-a"},
    {ChannelRole::CantileverB, "cantilever-b"},
    {ChannelRole::StiffBeam, "stiff-beam"},
    {ChannelRole::SoftBeam, "soft-beam"},
    {ChannelRole::Displacement, "displacement"},
    {ChannelRole::Capacitance, "capacitance"},
    {ChannelRole::ReferenceForce, "reference-force"},
    {ChannelRole::Position, "position"},
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

std::string_view toString(ChannelRole role)
{
    for (const auto& [r, name] : kRoleNames)
        if (r == role) return name;
    return {};
}

std::optional<ChannelRole> channelRoleFromString(std::string_view name)
{
    for (const auto& [r, n] : kRoleNames)
        if (n == name) return r;
    return std::nullopt;
}

std::string_view roleWord(const std::optional<ChannelRole>& role)
{
    return role ? toString(*role) : std::string_view();
}

std::string channelRoleChoices()
{
    std::string text;
    for (std::size_t i = 0; i < kRoleNames.size(); ++i) {
        if (i > 0) text += i + 1 == kRoleNames.size() ? " or " : ", ";
        text += kRoleNames[i].second;
    }
    return text;
}

std::optional<std::string> repeatedChannelName(std::span<const ChannelDescriptor> channels)
{
    std::set<std::string_view> seen;
    for (const ChannelDescriptor& c : channels)
        if (!seen.insert(c.name).second) return c.name;
    return std::nullopt;
}

}  // namespace tactiscope::core
