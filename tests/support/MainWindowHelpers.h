// What the main-window tests share: a live simulator as the device, an
// opener for a port path (an emulator's link), and a named child widget that
// must exist.
#pragma once

#include "devices/DeviceDiscovery.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <QWidget>

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace tactiscope::testing {

inline std::unique_ptr<devices::BlockSource> liveSimulator(const std::string& scenario = "panel-scan")
{
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(scenario));
}

inline devices::ReconnectingSource::Opener serialOpener(const std::string& path,
                                                        const devices::PortSourceOptions& options = {})
{
    return devices::deviceOpener({devices::DeviceBus::Serial, path, {}, path}, 921600, options);
}

template <typename Widget>
Widget* child(const QWidget& parent, const char* name)
{
    auto* widget = parent.findChild<Widget*>(QString::fromLatin1(name));
    EXPECT_NE(widget, nullptr) << name;
    return widget;
}

}  // namespace tactiscope::testing
