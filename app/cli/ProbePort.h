// Opening a probe on a serial port for a recording, as `record` does for
// one device or several: the first connection made at once (to know the
// device before the recording), then handed to a ReconnectingSource that
// reopens the port after an unplug, found again by its USB serial number.
#pragma once

#include "devices/ReconnectingSource.h"

#include <memory>
#include <string>

namespace tactiscope::cli {

// Throws what the first connection threw (the port cannot be opened, the
// device does not answer).
std::unique_ptr<devices::ReconnectingSource> openProbePort(const std::string& port, int baud,
                                                           const devices::PortSourceOptions& options);

}  // namespace tactiscope::cli
