// ChannelRoles: parsing "NAME=ROLE" lists and applying them to channels.
#include "core/modes/ChannelRoles.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core {
namespace {

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

}  // namespace

RoleAssignment parseRoleAssignment(std::string_view text)
{
    RoleAssignment roles;
    while (!trimmed(text).empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trimmed(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string_view::npos)
            throw std::invalid_argument("'" + std::string(item) + "' is not NAME=ROLE (e.g. a=cantilever-a)");
        const std::string name(trimmed(item.substr(0, equals)));
        const std::string_view roleText = trimmed(item.substr(equals + 1));
        if (name.empty()) throw std::invalid_argument("'" + std::string(item) + "' names no channel");
        const auto role = channelRoleFromString(roleText);
        if (!role)
            throw std::invalid_argument("'" + std::string(roleText) + "' is not a channel role; the roles are " +
                                        channelRoleChoices());
        if (roles.contains(name)) throw std::invalid_argument("channel '" + name + "' is given two roles");
        for (const auto& [other, given] : roles)
            if (given == *role)
                throw std::invalid_argument("the role " + std::string(roleText) + " is given to both '" + other +
                                            "' and '" + name + "'");
        roles.emplace(name, *role);
    }
    return roles;
}

std::string roleAssignmentText(const RoleAssignment& roles)
{
    std::string text;
    for (const auto& [name, role] : roles) {
        if (!text.empty()) text += ",";
        text += name + "=" + std::string(toString(role));
    }
    return text;
}

std::vector<ChannelDescriptor> applyRoles(std::span<const ChannelDescriptor> channels, const RoleAssignment& roles)
{
    std::vector<ChannelDescriptor> result(channels.begin(), channels.end());
    for (const auto& [name, role] : roles) {
        const auto named = std::ranges::find(result, name, &ChannelDescriptor::name);
        if (named == result.end()) {
            std::string names;
            for (const auto& channel : channels) names += (names.empty() ? "" : ", ") + channel.name;
            throw std::invalid_argument("no channel is named '" + name + "' to give the role " +
                                        std::string(toString(role)) +
                                        " (the channels: " + (names.empty() ? "none" : names) + ")");
        }
        for (auto& channel : result)
            if (channel.role == role) channel.role.reset();
        named->role = role;
    }
    return result;
}

}  // namespace tactiscope::core
