// Roles given to a device's channels by name: the command line's
// `--roles a=cantilever-a,b=cantilever-b`, the device panel's choices and a
// sensor profile's "roles" all come to a RoleAssignment, and applyRoles()
// puts them on the channels the device announced.
#pragma once

#include "core/ChannelDescriptor.h"

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core {

// Channel name → role. A role given here replaces the device's own for that
// channel; a channel not named keeps what the device declared.
using RoleAssignment = std::map<std::string, ChannelRole>;

// Parses "NAME=ROLE,NAME=ROLE". Throws std::invalid_argument naming the
// bad item: no '=', an unknown role (with the choices), a channel named
// twice, or one role given to two channels.
RoleAssignment parseRoleAssignment(std::string_view text);
// The same assignment written back ("a=cantilever-a,b=cantilever-b").
std::string roleAssignmentText(const RoleAssignment& roles);

// `channels` with the assigned roles; a role assigned here is taken from any
// other channel that declared it, so no role is played twice. Throws
// std::invalid_argument naming a channel there is not.
std::vector<ChannelDescriptor> applyRoles(std::span<const ChannelDescriptor> channels, const RoleAssignment& roles);

}  // namespace tactiscope::core
