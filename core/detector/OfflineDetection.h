// Offline analysis of series held in memory: the probe detector over
// complete series, optionally on several threads (StreamingDetection does
// the work; these are its whole-series forms, for tests and short spans).
#pragma once

#include "core/detector/DefectEvent.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/ProbeDetector.h"
#include "core/detector/StreamingDetection.h"

#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace tactiscope::core::detector {

struct SeriesInput {
    double t0_s = 0.0;                                 // time of the first sample
    std::vector<std::span<const double>> cantilevers;  // probe order, equal lengths, ≥ 2
    // Each sample's own time, when known (e.g. a file's t column); otherwise
    // times are t0_s + i·Δt.
    std::span<const double> times;
};

// The largest magnitude a sample may have: the detector sums squares and
// products over a window, and 1e150² summed over millions of samples still
// fits a double, where one 1e308 would make every later output inf or NaN.
inline constexpr double kLargestUsableValue = 1e150;

// The first sample the detector cannot use (not finite, or beyond
// kLargestUsableValue), as (cantilever, index); none when all can be used.
std::optional<std::pair<std::size_t, std::size_t>> firstUnusableSample(const SeriesInput& input);

// One ProbeOutput per sample. threads ≥ 1 (more than the lag groups is
// pointless and is reduced). Throws std::invalid_argument on bad input,
// including a sample without a value (NaN).
std::vector<ProbeOutput> detectSeries(const SeriesInput& input, const DetectorParameters& parameters,
                                      unsigned threads = 1);

// Events of a whole series (see EventSegmenter).
std::vector<DefectEvent> segmentEvents(std::span<const ProbeOutput> outputs, double sampleInterval_s, double hold_s,
                                       std::optional<double> spacing_m);

// Events of series that start at t = 0 and hold NaN where samples were lost:
// the detector runs over each stretch where every cantilever has a value and
// restarts after a gap, as a reconnection restarts the live detector.
// Throws std::invalid_argument on bad parameters.
StretchDetection detectStretches(std::span<const std::vector<double>> cantilevers, const StretchSettings& settings);

}  // namespace tactiscope::core::detector
