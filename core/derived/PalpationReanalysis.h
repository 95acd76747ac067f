// A palpation session's presses read again — through another probe profile
// or other gauge-factor calibrations — by the live reading's own code
// (compliance::PalpationForces and PressReader) over the stored samples, on
// the zeros the recording took (raw values, so they hold for any gauge
// factor). As live, a press in progress is dropped at a zero change, at a
// lost sample and at the end of the recording, and a press whose Q lies out
// of the probe's range is a state, not a reading. With the session's own
// profile and calibrations it gives the recorded readings again.
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tactiscope::core::derived {

// A palpation session's presses read by the live code over its stored
// samples: on the zeros the recording took when it has them, else as the
// live view takes its first zero — the mean of the first
// LivePalpation::kTare_s, the probe lifted — for a recording made by
// another program or the simulator and imported.
struct PalpationPresses {
    std::vector<compliance::PressReading> presses;  // in time order, out-of-range ones included
    std::string basis;                              // the profile and gauge factors, in words
    bool recordedZeros = false;                     // read on the recording's zeros
    // The probe's usable range (compliance::usableRange); none when its beams' counts are not known.
    std::optional<std::pair<double, double>> usableRange_n_per_m;
};

// Throws std::invalid_argument for channels the probe cannot read, a
// session shorter than the first zero or with samples lost in it;
// storage::StorageError.
PalpationPresses readPalpationPresses(storage::SessionSource& store, std::int64_t session,
                                      const sensors::CompliancePairProfile& probe,
                                      const std::vector<calibration::CalibrationRecord>& calibrations);

// Every sample of a palpation session with its forces in N, on the same
// zeros as readPalpationPresses (for the paper's step reading).
struct ForceSample {
    double t_s = 0.0;
    double displacement_m = 0.0;
    double forceHigh_n = 0.0;
    double forceLow_n = 0.0;
    compliance::BeamLimits atLimit;  // each beam's ADC at its limit
};
struct PalpationForceSamples {
    std::vector<ForceSample> samples;  // in time order, lost ones left out
    std::string basis;
    bool recordedZeros = false;
    double contactThreshold_n = 0.0;
};
PalpationForceSamples readPalpationForces(storage::SessionSource& store, std::int64_t session,
                                          const sensors::CompliancePairProfile& probe,
                                          const std::vector<calibration::CalibrationRecord>& calibrations);

struct PalpationReanalysis {
    std::vector<storage::SessionReading> readings;  // as the recording stores them, analysis unset
    std::size_t outOfRange = 0;                     // presses read out of the probe's range
    std::string basis;                              // the profile and gauge factors, in words
};

// Each reading takes the site of the recorded reading it overlaps, else the
// session's. Throws std::invalid_argument for a session that is not a
// palpation one or channels the probe cannot read; storage::StorageError.
PalpationReanalysis reanalysePalpation(storage::SessionSource& store, std::int64_t session,
                                       const sensors::CompliancePairProfile& probe,
                                       const std::vector<calibration::CalibrationRecord>& calibrations);

}  // namespace tactiscope::core::derived
