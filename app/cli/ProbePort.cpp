// ProbePort: the first connection, then reconnection by USB serial number.
#include "ProbePort.h"

#include "devices/transport/SerialPorts.h"

#include <filesystem>

namespace tactiscope::cli {

namespace {

// The USB serial number of the port behind `path` (a link is followed), so a
// replugged probe is found again even under another name.
std::string usbSerialOf(const std::string& path)
{
    std::error_code error;
    const auto resolved = std::filesystem::canonical(path, error);
    if (error) return {};
    for (const auto& port : devices::transport::listSerialPorts()) {
        if (port.path == resolved.string()) return port.usbSerialNumber;
    }
    return {};
}

}  // namespace

std::unique_ptr<devices::ReconnectingSource> openProbePort(const std::string& port, int baud,
                                                           const devices::PortSourceOptions& options)
{
    const auto reopen = devices::serialOpener(port, usbSerialOf(port), baud, options);
    auto handover = std::make_shared<std::unique_ptr<devices::BlockSource>>(reopen());
    return std::make_unique<devices::ReconnectingSource>(
        [handover, reopen] { return *handover ? std::move(*handover) : reopen(); });
}

}  // namespace tactiscope::cli
