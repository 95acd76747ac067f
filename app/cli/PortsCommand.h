// `tactiscope-cli ports`: the serial ports and HID devices a probe may be on.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runPorts(const QStringList& arguments);

}  // namespace tactiscope::cli
