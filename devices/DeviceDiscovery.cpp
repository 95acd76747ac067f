// Device discovery over libserialport and hidapi, and the openers.
#include "devices/DeviceDiscovery.h"

#include "devices/transport/HidTransport.h"
#include "devices/transport/SerialPorts.h"

#include <cstdio>

namespace tactiscope::devices {
namespace {

std::string usbIds(int vendor, int product)
{
    return usbIdText(vendor) + ":" + usbIdText(product);
}

}  // namespace

std::string usbIdText(int id)
{
    char text[8];
    std::snprintf(text, sizeof text, "%04x", id & 0xffff);
    return text;
}

Discovery discoverDevices()
{
    Discovery found;
    auto& devices = found.devices;
    for (const auto& port : transport::listSerialPorts()) {
        std::string description = port.description.empty() ? port.path : port.description;
        if (port.usbVendorId && port.usbProductId)
            description += " (USB " + usbIds(*port.usbVendorId, *port.usbProductId) + ")";
        devices.push_back({DeviceBus::Serial, port.path, port.usbSerialNumber, description});
    }
    try {
        for (const auto& hid : transport::listHidDevices()) {
            std::string description = hid.manufacturer.empty() ? hid.product : hid.manufacturer + " " + hid.product;
            description += " (HID " + usbIds(hid.vendorId, hid.productId) + ")";
            devices.push_back({DeviceBus::Hid, hid.path, hid.serialNumber, description});
        }
    } catch (const transport::TransportError& e) {
        found.hidError = e.what();  // the serial ports are still worth showing
    }
    return found;
}

ReconnectingSource::Opener deviceOpener(const DiscoveredDevice& device, int baud, const PortSourceOptions& options)
{
    if (device.bus == DeviceBus::Serial) return serialOpener(device.path, device.usbSerialNumber, baud, options);
    PortSourceOptions binary = options;
    binary.protocol = WireProtocol::Binary;
    return [path = device.path, serial = device.usbSerialNumber, binary]() -> std::unique_ptr<BlockSource> {
        std::string where = path;
        if (!serial.empty()) {
            for (const auto& hid : transport::listHidDevices()) {
                if (hid.serialNumber == serial) where = hid.path;
            }
        }
        return std::make_unique<PortSource>(transport::openHidTransport(where), binary);
    };
}

}  // namespace tactiscope::devices
