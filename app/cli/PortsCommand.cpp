// The ports subcommand.
#include "PortsCommand.h"

#include "CliSupport.h"
#include "core/text/JsonWriter.h"
#include "devices/DeviceDiscovery.h"
#include "devices/transport/HidTransport.h"
#include "devices/transport/SerialPorts.h"

#include <QTextStream>

#include <iostream>

namespace tactiscope::cli {
int runPorts(const QStringList& arguments)
{
    const QString name = QStringLiteral("ports");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("List serial ports and HID devices."));
    parser.addOption({QStringLiteral("json"), QStringLiteral("Print one JSON object.")});
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument %1").arg(quoted(parser.positionalArguments().front())),
                          commandUsage(parser, name));

    const auto serial = devices::transport::listSerialPorts();
    std::vector<devices::transport::HidDeviceInfo> hid;
    try {
        hid = devices::transport::listHidDevices();
    } catch (const devices::transport::TransportError& e) {
        printError(QString::fromStdString(e.what()));  // keep the serial list
    }
    if (parser.isSet(QStringLiteral("json"))) {
        core::text::JsonWriter json;
        json.beginObject().key("serial").beginArray();
        for (const auto& p : serial) {
            json.beginObject();
            json.key("path").value(p.path);
            json.key("description").value(p.description);
            json.key("transport").value(p.transport);
            if (p.usbVendorId) json.key("usb_vid").value(devices::usbIdText(*p.usbVendorId));
            if (p.usbProductId) json.key("usb_pid").value(devices::usbIdText(*p.usbProductId));
            if (!p.usbSerialNumber.empty()) json.key("usb_serial").value(p.usbSerialNumber);
            json.endObject();
        }
        json.endArray().key("hid").beginArray();
        for (const auto& d : hid) {
            json.beginObject();
            json.key("path").value(d.path);
            json.key("vid").value(devices::usbIdText(d.vendorId));
            json.key("pid").value(devices::usbIdText(d.productId));
            json.key("serial").value(d.serialNumber);
            json.key("manufacturer").value(d.manufacturer);
            json.key("product").value(d.product);
            json.endObject();
        }
        json.endArray().endObject();
        std::cout << json.str() << '\n';
        return kExitOk;
    }
    QTextStream out(stdout);
    out << "Serial ports (" << serial.size() << "):\n";
    for (const auto& p : serial) {
        out << "  " << QString::fromStdString(p.path) << "  " << QString::fromStdString(p.description);
        if (p.usbVendorId)
            out << "  USB " << QString::fromStdString(devices::usbIdText(*p.usbVendorId)) << ":"
                << QString::fromStdString(devices::usbIdText(*p.usbProductId));
        if (!p.usbSerialNumber.empty()) out << "  serial " << QString::fromStdString(p.usbSerialNumber);
        out << '\n';
    }
    out << "HID devices (" << hid.size() << "):\n";
    for (const auto& d : hid) {
        out << "  " << QString::fromStdString(d.path) << "  " << QString::fromStdString(devices::usbIdText(d.vendorId))
            << ":" << QString::fromStdString(devices::usbIdText(d.productId)) << "  "
            << QString::fromStdString(d.manufacturer) << " " << QString::fromStdString(d.product) << '\n';
    }
    if (serial.empty() && hid.empty())
        out << "Nothing found. Is the probe plugged in? Without one, try: tactiscope-cli emulate --link /tmp/probe\n";
    return kExitOk;
}

}  // namespace tactiscope::cli
