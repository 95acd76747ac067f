// Sharing DEVICE/VALUE options out to a session's devices.
#include "DeviceValues.h"

#include "CliSupport.h"

#include <QRegularExpression>

#include <algorithm>

namespace tactiscope::cli {

namespace {

// The first "DEVICE/NAME" in `expression` naming one of `devices` (without
// spaces around the '/', as a channel of that device would be written);
// empty when there is none.
QString deviceQualifiedName(const QString& expression, const std::vector<std::string>& devices)
{
    for (const std::string& device : devices) {
        const QRegularExpression qualified(
            QStringLiteral("(?<![\\w.])%1/[A-Za-z_]\\w*").arg(QRegularExpression::escape(toQString(device))));
        if (const auto match = qualified.match(expression); match.hasMatch()) return match.captured();
    }
    return {};
}

}  // namespace

QString devicesText(const std::vector<std::string>& devices)
{
    QStringList names;
    for (const std::string& name : devices) names.append(toQString(name));
    return QStringLiteral("the devices: %1").arg(names.join(QStringLiteral(", ")));
}

std::optional<std::vector<QStringList>> valuesByDevice(const QString& option, const QString& form,
                                                       const QStringList& values,
                                                       const std::vector<std::string>& devices, QString& error)
{
    std::vector<QStringList> byDevice(devices.size());
    for (const QString& value : values) {
        const auto split = deviceAndChannel(value.toStdString());
        const auto device = split ? std::ranges::find(devices, split->first) : devices.end();
        if (device == devices.end()) {
            const QString why = split ? QStringLiteral("no device is named %1").arg(quoted(toQString(split->first)))
                                      : QStringLiteral("with several devices, say whose as %1").arg(form);
            error = QStringLiteral("--%1 %2: %3 (%4)").arg(option, quoted(value), why, devicesText(devices));
            return std::nullopt;
        }
        const QString own = toQString(split->second);
        if (option == QLatin1String("math")) {
            const QString expression = own.mid(own.indexOf(QLatin1Char('=')) + 1);
            if (const QString name = deviceQualifiedName(expression, devices); !name.isEmpty()) {
                const QString channel = name.mid(name.indexOf(QLatin1Char('/')) + 1);
                error = QStringLiteral("--math %1: %2 would read as a division; a math channel is over its own "
                                       "device's channels, named without a device (the devices' clocks differ): "
                                       "%3, not %2 (for a division, write %4)")
                            .arg(quoted(value), quoted(name), quoted(channel),
                                 quoted(QString(name).replace(QLatin1Char('/'), QStringLiteral(" / "))));
                return std::nullopt;
            }
        }
        byDevice[static_cast<std::size_t>(device - devices.begin())].append(own);
    }
    return byDevice;
}

}  // namespace tactiscope::cli
