// How one sensor's calibrations have moved over time: the spread of a
// calibrated value (a gauge factor, a sensitivity) across its records, the
// change from the first to the newest, and the linear trend per year, so
// a reviewer sees whether a sensor ages, and how fast.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace tactiscope::core::calibration {

struct DriftSummary {
    std::size_t count = 0;
    double mean = 0.0;
    double standardDeviation = 0.0;  // sample (n − 1); 0 for one record
    double firstToLast = 0.0;        // (newest − oldest) / oldest
    // Least-squares slope against time, per year of 365.25 days; none when
    // all records share one time.
    std::optional<double> trendPerYear;
};

// t_s: each record's time (seconds, any epoch), in any order; values alike.
// Throws std::invalid_argument for no values or unequal lengths.
DriftSummary summarizeDrift(std::span<const double> t_s, std::span<const double> values);

}  // namespace tactiscope::core::calibration
