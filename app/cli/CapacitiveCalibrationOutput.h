// What `calibrate-capacitive` prints: the calibration and its steps as
// text or as one JSON object, and for a sweep against a reference force
// (issue 40) what the pairing rests on: the reference, its zero, the
// sweep, and the two clocks' timing with the force it can shift a point by.
#pragma once

#include "core/calibration/CapacitiveCalibration.h"
#include "core/calibration/CapacitiveSteps.h"

#include <cstddef>
#include <optional>
#include <string>

namespace tactiscope::cli {

struct SweepReport {
    std::string reference;    // "load-cell/force"
    std::string capacitance;  // "beam/capacitance"
    double zero_n = 0.0;
    double span_n = 0.0;
    std::size_t turns = 0;
    double lag_s = 0.0;       // the beam's time constant, taken out
    std::size_t paired = 0;   // beam samples with a reference value
    std::size_t outside = 0;  // without one, left out
    std::optional<double> clockUncertainty_s;
    double steepest_n_per_s = 0.0;
};

void writeCapacitiveJson(const core::calibration::CapacitiveCalibrationResult& result,
                         const core::calibration::CapacitiveSteps& steps, bool timed, const SweepReport* sweep);
void writeCapacitiveText(const core::calibration::CapacitiveCalibrationResult& result,
                         const core::calibration::CapacitiveSteps& steps, bool timed, const SweepReport* sweep);

}  // namespace tactiscope::cli
