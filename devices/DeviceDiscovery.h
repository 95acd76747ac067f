// The device manager's view of what is plugged in: serial ports and HID
// devices in one list, and how to open (and later reopen) one of them as a
// ReconnectingSource. The GUI's connect dialog and `tactiscope-cli ports`
// show the same list.
#pragma once

#include "devices/PortSource.h"
#include "devices/ReconnectingSource.h"

#include <string>
#include <vector>

namespace tactiscope::devices {

enum class DeviceBus { Serial, Hid };

struct DiscoveredDevice {
    DeviceBus bus = DeviceBus::Serial;
    std::string path;             // /dev/ttyACM0, or a hidraw path
    std::string usbSerialNumber;  // empty when unknown
    std::string description;      // what a user recognises, e.g. "Arduino Uno (USB 2341:0043)"
};

struct Discovery {
    std::vector<DiscoveredDevice> devices;
    std::string hidError;  // why HID devices could not be listed, if they could not
};

Discovery discoverDevices();

// A USB vendor or product id as four lower-case hex digits, e.g. "2341".
std::string usbIdText(int id);

// An opener that finds the device again by USB serial number when it has
// one (its path may change after a replug), else by path. HID devices always
// speak TSP/1; `baud` and the text settings apply to serial ports only.
ReconnectingSource::Opener deviceOpener(const DiscoveredDevice& device, int baud, const PortSourceOptions& options);

}  // namespace tactiscope::devices
