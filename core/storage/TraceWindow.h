// What a review plot of one stored channel shows over a time span at a given
// width: the exact samples when there are few enough to tell apart (a few
// per pixel), otherwise the exact min and max of each pixel's stretch from
// the store's overview pyramid. So zooming reads only what is on screen, and
// the whole of an hour-long session costs about one read per pixel.
#pragma once

#include "core/storage/SessionStore.h"

#include <cstdint>
#include <vector>

namespace tactiscope::core::storage {

struct TraceWindow {
    bool exact = false;
    std::uint64_t firstIndex = 0;  // exact: the index of the first sample
    // Exact: each sample's time and value (low == high; NaN where lost).
    // Otherwise: the middle of each stretch and its min and max.
    std::vector<double> t_s;
    std::vector<double> low;
    std::vector<double> high;

    // The point nearest to t, or -1 when the window is empty.
    long long nearest(double t_s) const;
};

// Samples per pixel at or below which the exact samples are read.
inline constexpr double kExactSamplesPerPixel = 4.0;

// The window of `channel` over [from_s, to_s] (session seconds, clipped to
// the recording) for a plot `pixels` wide. One sample beyond each end is
// included when exact, so a line reaches the plot's edges.
TraceWindow readTraceWindow(SessionStore& store, std::int64_t session, std::size_t channel, double sampleRate_hz,
                            std::uint64_t sampleCount, double from_s, double to_s, std::size_t pixels);

}  // namespace tactiscope::core::storage
