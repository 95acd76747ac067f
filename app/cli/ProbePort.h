// Opening a probe on a serial port for a recording, as `record` does for
// one device or several: each --port value read as [NAME=]PATH, the first
// connection made at once (to know the device before the recording), then
// handed to a ReconnectingSource that reopens the port after an unplug,
// found again by its USB serial number.
#pragma once

#include "devices/ReconnectingSource.h"

#include <QStringList>

#include <memory>
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

// Throws what the first connection threw (the port cannot be opened, the
// device does not answer).
std::unique_ptr<devices::ReconnectingSource> openProbePort(const std::string& port, int baud,
                                                           const devices::PortSourceOptions& options);

}  // namespace tactiscope::cli
