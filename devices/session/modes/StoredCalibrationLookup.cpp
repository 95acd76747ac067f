// StoredCalibrationLookup: a store that cannot be read is told, not thrown.
#include "devices/session/modes/StoredCalibrationLookup.h"

namespace tactiscope::devices::session {

std::optional<core::storage::StoredCalibration> newestCalibration(const LiveUnitSetup& setup, std::string_view kind,
                                                                  const std::string& sensor)
{
    try {
        return core::storage::newestCalibrationIn(setup.storePath, kind, sensor);
    } catch (const core::storage::StorageError& e) {
        if (setup.problems)
            setup.problems->push_back("the calibrations of '" + sensor + "' could not be read from " + setup.storePath +
                                      " (its nominal values are used): " + e.what());
        return std::nullopt;
    }
}

}  // namespace tactiscope::devices::session
