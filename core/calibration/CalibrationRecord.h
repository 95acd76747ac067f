// A calibration result as it is stored and shown: what was calibrated, by
// whom and when, the values it produced (names carry their units, e.g.
// "counts_per_newton") and the statistics of the fit behind them.
#pragma once

#include "core/calibration/LinearFit.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tactiscope::core::calibration {

// The kinds of record, as stored.
inline constexpr std::string_view kGaugeFactorKind = "gauge_factor";  // a strain-gauged beam's gauge factor
inline constexpr std::string_view kCapacitiveKind = "capacitive";     // the capacitive beam's C0 and sensitivity
inline constexpr std::string_view kShuntCheckKind = "shunt_check";    // a strain channel's shunt check, passed or not

// The sensor a record belongs to. A compliance probe's two strain-gauged
// beams are sensors of their own ("<probe> — stiff beam"), since each
// beam's gauge has its own factor; a capacitive beam is its profile's name.
std::string beamSensorName(const std::string& probeName, bool stiffBeam);

struct CalibrationRecord {
    std::string kind;  // kGaugeFactorKind, kCapacitiveKind, …
    std::string sensorName;
    std::string operatorName;
    std::string timestampUtc;  // ISO 8601, e.g. 2026-11-21T13:40:00Z
    std::vector<std::pair<std::string, double>> values;
    LinearFit fit;

    std::optional<double> value(const std::string& name) const;
    // One JSON object with all of the above.
    std::string toJson() const;
    // Reads toJson()'s form back. Throws std::invalid_argument.
    static CalibrationRecord fromJson(std::string_view json);
};

// The records a session carries (storage::SessionMetadata::calibrationsJson,
// a JSON array of toJson() objects); one that cannot be read is left out,
// so one damaged record does not hide the others.
std::vector<CalibrationRecord> recordsFromJsonArray(const std::string& json);

// The current time as ISO 8601 UTC with seconds.
std::string utcTimestampNow();

}  // namespace tactiscope::core::calibration
