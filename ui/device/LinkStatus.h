// The link's counters as the device panel and the status bar show them:
// the acquisition's state, rate and losses, and for a device that can be
// unplugged, whether it is away and how often it came back.
#pragma once

#include "ui/device/DevicePanel.h"

namespace tactiscope::devices {
class BlockSource;
struct AcquisitionStats;
}  // namespace tactiscope::devices

namespace tactiscope::ui {

LinkCounters linkCounters(const devices::AcquisitionStats& stats, const devices::BlockSource& source);
// One line for the status bar: "Streaming · 500.0 Hz · 12 lost".
QString linkLine(const LinkCounters& counters);

}  // namespace tactiscope::ui
