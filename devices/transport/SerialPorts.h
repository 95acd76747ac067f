// Serial ports: listing them with their USB identity, and opening one with
// the right backend. Choosing the backend happens here and nowhere else:
//   - pseudo-terminals (/dev/pts/*, and links to them) go straight to the
//     POSIX termios backend, because Debian's libserialport 0.1.1 cannot
//     open them (sp_get_port_by_name wants a /sys/class/tty entry; sp_open
//     fails on the TIOCMGET modem-line ioctl);
//   - everything else goes through libserialport, falling back to termios
//     when libserialport refuses the port for a reason other than
//     permissions or a busy port (which termios would hit too).
#pragma once

#include "devices/transport/Transport.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::transport {

struct SerialPortInfo {
    std::string path;  // /dev/ttyACM0
    std::string description;
    std::string transport;  // "usb", "native", "bluetooth"
    std::optional<int> usbVendorId;
    std::optional<int> usbProductId;
    std::string usbSerialNumber;  // empty when not a USB port or unknown
};

std::vector<SerialPortInfo> listSerialPorts();

// Throws TransportError with a message a user can act on.
std::unique_ptr<Transport> openSerialTransport(const std::string& path, int baud);

}  // namespace tactiscope::devices::transport
