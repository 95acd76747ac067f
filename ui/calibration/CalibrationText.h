// Calibration records in words, for the live views, the wizards, the
// history and the reports alike, so one value reads the same everywhere
// (the sensitivity was 1.80751 in one place and 1.8075 in another).
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/storage/SessionRecords.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace tactiscope::ui {

// "beam A, calibrated 11/23/26 8:00:00 AM by Ada; …": the calibrations a
// live view reads through, on screen; empty for none.
QString calibrationsText(const std::vector<core::storage::StoredCalibration>& calibrations);

// A record's values as labelled rows with units ("Sensitivity 1.8075 ±
// 0.0022 pF/mN"), never its key names; a value with its standard
// uncertainty to the uncertainty's decimals, one without to four digits; a
// force or length without one with its SI prefix ("20.1 µN (2.05 mgf)").
QStringList calibrationValueTexts(const core::calibration::CalibrationRecord& record);

// A capacitive detection limit as force and as mass: "7.60 µN (0.775 mgf)".
QString detectionLimitText(double limit_n);

}  // namespace tactiscope::ui
