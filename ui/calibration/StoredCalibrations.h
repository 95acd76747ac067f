// The calibration records of the session store as the live views and the
// wizards use them: the newest record of a kind for a sensor is the active
// one (sensor names: core::calibration::beamSensorName).
#pragma once

#include "core/storage/SessionRecords.h"

#include <QString>

class QWidget;

#include <optional>
#include <string>

namespace tactiscope::ui {

// None when the store does not exist or cannot be read (logged).
std::optional<core::storage::StoredCalibration> newestCalibration(const QString& storePath, std::string_view kind,
                                                                  const std::string& sensor);

// Stores the record and returns its id. Throws core::storage::StorageError.
std::int64_t storeCalibration(const QString& storePath, const core::calibration::CalibrationRecord& record);
// The same for a wizard's Accept: a failure is told in a message box over
// `parent`, and the wizard stays open with nothing lost.
std::optional<std::int64_t> storeCalibrationOrSay(QWidget* parent, const QString& storePath,
                                                  const core::calibration::CalibrationRecord& record);

}  // namespace tactiscope::ui
