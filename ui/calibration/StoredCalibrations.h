// Adding a wizard's calibration record to the session store (reading the
// newest one: core::storage::newestCalibrationIn).
#pragma once

#include "core/storage/SessionRecords.h"

#include <QString>

class QWidget;

#include <optional>
#include <string>

namespace tactiscope::ui {

// Stores the record and returns its id. Throws core::storage::StorageError.
std::int64_t storeCalibration(const QString& storePath, const core::calibration::CalibrationRecord& record);
// The same for a wizard's Accept: a failure is told in a message box over
// `parent`, and the wizard stays open with nothing lost.
std::optional<std::int64_t> storeCalibrationOrSay(QWidget* parent, const QString& storePath,
                                                  const core::calibration::CalibrationRecord& record);

}  // namespace tactiscope::ui
