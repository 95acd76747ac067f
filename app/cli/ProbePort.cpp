// ProbePort: the --port values, the first connection, then reconnection
// by USB serial number.
#include "ProbePort.h"

#include "devices/transport/SerialPorts.h"

#include <algorithm>
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

bool isDeviceName(const std::string& name)
{
    return !name.empty() && std::ranges::none_of(name, [](char c) { return c == '/' || c == '=' || c == ' '; });
}

}  // namespace

std::optional<std::vector<ProbePortArgument>> parseProbePorts(const QStringList& values)
{
    std::vector<ProbePortArgument> ports;
    for (const QString& value : values) {
        const auto equals = value.indexOf(QLatin1Char('='));
        ProbePortArgument port{{}, value.toStdString()};
        if (equals >= 0) {
            port.name = value.left(equals).toStdString();
            port.path = value.mid(equals + 1).toStdString();
            if (!isDeviceName(port.name) || port.path.empty()) return std::nullopt;
            if (std::ranges::any_of(ports, [&](const ProbePortArgument& p) { return p.name == port.name; }))
                return std::nullopt;
        }
        ports.push_back(std::move(port));
    }
    if (ports.empty()) return std::nullopt;
    return ports;
}

std::unique_ptr<devices::ReconnectingSource> openProbePort(const std::string& port, int baud,
                                                           const devices::PortSourceOptions& options)
{
    const auto reopen = devices::serialOpener(port, usbSerialOf(port), baud, options);
    auto handover = std::make_shared<std::unique_ptr<devices::BlockSource>>(reopen());
    return std::make_unique<devices::ReconnectingSource>(
        [handover, reopen] { return *handover ? std::move(*handover) : reopen(); });
}

}  // namespace tactiscope::cli
