// What a calibration wizard works with: the connected device's live samples
// and channels, its clock on the host's, the other devices already in the
// session (a reference is read from them, never opened twice), the
// simulator's load rig when the device is the simulator, the window's store
// worker its record goes to, who calibrates and where the profiles are.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/storage/StoreWorker.h"
#include "core/timing/ClockAlignment.h"
#include "devices/simulator/LoadRig.h"

#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace tactiscope::ui {

// A device whose channels a wizard can read a reference from, with what
// pairs its samples with the calibrated device's.
struct ReferenceDevice {
    QString name;    // how the user knows it: "load-cell"
    QString source;  // its source's description, with its port
    std::vector<core::ChannelDescriptor> channels;
    std::shared_ptr<const core::LiveBuffer> buffer;
    double sampleRate_hz = 0.0;
    // Its clock on the host's steady clock; none once it left the session.
    std::function<std::optional<core::timing::ClockMapping>()> hostClock;
};

struct CalibrationContext {
    std::shared_ptr<const core::LiveBuffer> buffer;  // every channel of the device
    std::vector<core::ChannelDescriptor> channels;
    double sampleRate_hz = 0.0;
    // The simulator's rig: the wizard hangs each load itself. Null for a
    // real probe, where the operator does.
    std::shared_ptr<devices::simulator::LoadRig> rig;
    std::shared_ptr<core::storage::StoreWorker> store;
    QString operatorName;
    QString profileDirectory;
    // The device's clock on the host's steady clock, as now estimated
    // (devices::BlockSource::hostClock), for pairing its samples with
    // another device's; unset or none: not known.
    std::function<std::optional<core::timing::ClockMapping>()> hostClock;
    // The session's other devices, as they are now; unset: none.
    std::function<std::vector<ReferenceDevice>()> sessionDevices;
};

}  // namespace tactiscope::ui
