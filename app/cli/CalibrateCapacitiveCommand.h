// `tactiscope-cli calibrate-capacitive READINGS.csv`: C0, sensitivity and
// detection limit of a capacitive beam from recorded (force, capacitance)
// pairs; rows with force 0 form the baseline.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runCalibrateCapacitive(const QStringList& arguments);

}  // namespace tactiscope::cli
