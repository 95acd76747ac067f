// The newest calibration of a sensor in the session store, for the units
// that read through one; a store that exists but cannot be read is a
// problem to tell (the unit then reads through the nominal values).
#pragma once

#include "core/storage/SessionStore.h"
#include "devices/session/LiveModeUnit.h"

#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::devices::session {

std::optional<core::storage::StoredCalibration> newestCalibration(const LiveUnitSetup& setup, std::string_view kind,
                                                                  const std::string& sensor);

}  // namespace tactiscope::devices::session
