// `record --port NAME=PATH --port NAME=PATH …`: several probes recorded into
// one session (devices/session/SessionOfDevices), each device a part with
// its own rate, clock, gaps and analysis, its clock mapped onto the
// session's and stored with its uncertainty. Prints one contract line for
// the session ("Recorded session N: …", as for one device) and a line per
// device with its samples, losses and clock.
#pragma once

#include "core/modes/ChannelRoles.h"
#include "core/storage/SessionSource.h"
#include "devices/PortSource.h"

#include <QStringList>

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::cli {

struct ProbePortArgument {
    std::string name;  // empty: the device's model, made unique
    std::string path;
};

// Each --port value, "NAME=PATH" or "PATH"; none when a name is not a word
// (empty, or holding '/', '=' or a space) or is given twice.
std::optional<std::vector<ProbePortArgument>> parseProbePorts(const QStringList& values);

struct DevicesRecording {
    std::vector<ProbePortArgument> ports;
    std::string db;
    devices::PortSourceOptions options;
    int baud = 0;
    std::optional<double> seconds;
    core::storage::SessionMetadata metadata;
    // By "DEVICE/CHANNEL": each device's channels' roles.
    core::RoleAssignment roles;
};

int recordDevices(const DevicesRecording& setup);

}  // namespace tactiscope::cli
