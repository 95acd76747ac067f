// How one sensor's calibrations have moved over time: the spread of a
// calibrated value (a gauge factor, a sensitivity) across its records, the
// change from the first to the newest, and the linear trend per year with
// its uncertainty, so a reviewer sees whether a sensor ages, and how fast.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace tactiscope::core::calibration {

// A trend is stated from this many records over this span at least: two
// records minutes apart make a slope, not a trend.
constexpr std::size_t kTrendRecords = 10;
constexpr double kTrendSpan_s = 30.0 * 86400.0;

struct DriftTrend {
    double perYear = 0.0;  // least-squares slope against time, per year of 365.25 days
    // Its standard uncertainty: the slope's standard error widened to the
    // spread of Student's t with n − 2 degrees of freedom (√(ν/(ν − 2))),
    // so ±1u and ±2u cover the true slope about as a Gaussian's do.
    double uncertaintyPerYear = 0.0;
};

struct DriftSummary {
    std::size_t count = 0;
    double mean = 0.0;
    double standardDeviation = 0.0;  // sample (n − 1); 0 for one record
    double firstToLast = 0.0;        // (newest − oldest) / oldest
    double span_s = 0.0;             // newest − oldest
    // None below kTrendRecords records or a span of kTrendSpan_s.
    std::optional<DriftTrend> trend;
};

// t_s: each record's time (seconds, any epoch), in any order; values alike.
// Throws std::invalid_argument for no values or unequal lengths.
DriftSummary summarizeDrift(std::span<const double> t_s, std::span<const double> values);

}  // namespace tactiscope::core::calibration
