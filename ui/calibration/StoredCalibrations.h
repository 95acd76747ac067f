// The calibration records as the live views name them, and adding a
// wizard's record to the session store (reading the newest one:
// core::storage::newestCalibrationIn).
#pragma once

#include "core/storage/SessionRecords.h"

#include <QString>

class QWidget;

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::ui {

// "beam A on 2026-11-23T08:00:00Z by Ada, …": the calibrations a view reads
// through; empty for none.
QString calibrationsText(const std::vector<core::storage::StoredCalibration>& calibrations);

// Stores the record and returns its id. Throws core::storage::StorageError.
std::int64_t storeCalibration(const QString& storePath, const core::calibration::CalibrationRecord& record);
// The same for a wizard's Accept: a failure is told in a message box over
// `parent`, and the wizard stays open with nothing lost.
std::optional<std::int64_t> storeCalibrationOrSay(QWidget* parent, const QString& storePath,
                                                  const core::calibration::CalibrationRecord& record);

}  // namespace tactiscope::ui
