// ChannelRoles: parsing "NAME=ROLE" lists and applying them to channels.
#include "core/modes/ChannelRoles.h"

#include "core/text/NamedList.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core {

RoleAssignment parseRoleAssignment(std::string_view text)
{
    RoleAssignment roles;
    for (const auto& [name, roleText] : text::parseNamedList(text, "NAME=ROLE (e.g. a=cantilever-a)", "role")) {
        const auto role = channelRoleFromString(roleText);
        if (!role)
            throw std::invalid_argument("'" + roleText + "' is not a channel role; the roles are " +
                                        channelRoleChoices());
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
