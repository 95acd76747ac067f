// The calibration records a live view reads through, named for a person
// (reading the newest one: core::storage::newestCalibrationIn; a wizard
// stores its record through CalibrationWizard).
#pragma once

#include "core/storage/SessionRecords.h"

#include <QString>

#include <vector>

namespace tactiscope::ui {

// "beam A on 2026-11-23T08:00:00Z by Ada, …": the calibrations a view reads
// through; empty for none.
QString calibrationsText(const std::vector<core::storage::StoredCalibration>& calibrations);

}  // namespace tactiscope::ui
