// Values of a session of several devices given as DEVICE/VALUE
// (--filter-channel a/x, --math "a/diff[µε]=x - y"), shared out to the
// devices, by `record` and `sessions export` alike.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::cli {

// "the devices: a, b", for messages.
QString devicesText(const std::vector<std::string>& devices);

// Each device's values of option --OPTION (given as `form`, such as
// "DEVICE/CHANNEL"), without their "DEVICE/", in `devices`' order. None,
// with the usage error in `error`, for a value without a device or with
// one not in `devices`; and for --math, for an expression that names a
// device's channel as DEVICE/CHANNEL, which it would read as a division
// (a math channel is over its own device's channels: the clocks differ).
std::optional<std::vector<QStringList>> valuesByDevice(const QString& option, const QString& form,
                                                       const QStringList& values,
                                                       const std::vector<std::string>& devices, QString& error);

}  // namespace tactiscope::cli
