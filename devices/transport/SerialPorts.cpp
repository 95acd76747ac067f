// Port listing and the choice of serial backend.
#include "devices/transport/SerialPorts.h"

#include "devices/transport/ReadAheadTransport.h"

#include "devices/transport/LibSerialPortTransport.h"
#include "devices/transport/PosixSerialTransport.h"

#include <libserialport.h>

#include <filesystem>

namespace tactiscope::devices::transport {
namespace {

bool isPseudoTerminal(const std::string& path)
{
    std::error_code error;
    const auto resolved = std::filesystem::canonical(path, error);
    return !error && resolved.string().rfind("/dev/pts/", 0) == 0;
}

}  // namespace

std::vector<SerialPortInfo> listSerialPorts()
{
    std::vector<SerialPortInfo> result;
    sp_port** ports = nullptr;
    if (sp_list_ports(&ports) != SP_OK) return result;
    for (sp_port** p = ports; *p; ++p) {
        SerialPortInfo info;
        info.path = sp_get_port_name(*p);
        if (const char* d = sp_get_port_description(*p)) info.description = d;
        switch (sp_get_port_transport(*p)) {
        case SP_TRANSPORT_USB: {
            info.transport = "usb";
            int vid = 0, pid = 0;
            if (sp_get_port_usb_vid_pid(*p, &vid, &pid) == SP_OK) {
                info.usbVendorId = vid;
                info.usbProductId = pid;
            }
            if (const char* serial = sp_get_port_usb_serial(*p)) info.usbSerialNumber = serial;
            break;
        }
        case SP_TRANSPORT_BLUETOOTH:
            info.transport = "bluetooth";
            break;
        default:
            info.transport = "native";
        }
        result.push_back(std::move(info));
    }
    sp_free_port_list(ports);
    return result;
}

namespace {

std::unique_ptr<Transport> openPort(const std::string& path, int baud)
{
    if (isPseudoTerminal(path)) return std::make_unique<PosixSerialTransport>(path, baud);
    try {
        return std::make_unique<LibSerialPortTransport>(path, baud);
    } catch (const TransportError&) {
        // Permission or busy errors come back from termios too, with the fix;
        // anything else libserialport disliked may still open there.
        return std::make_unique<PosixSerialTransport>(path, baud);
    }
}

}  // namespace

// Read ahead, so the port's few kilobytes never fill while the host is busy.
std::unique_ptr<Transport> openSerialTransport(const std::string& path, int baud)
{
    return std::make_unique<ReadAheadTransport>(openPort(path, baud));
}

}  // namespace tactiscope::devices::transport
