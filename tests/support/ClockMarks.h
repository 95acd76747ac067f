// Finding a clock mark (devices/simulator/ClockMark.h) in recorded samples
// alone, on the times they were given: first roughly, where the fastest
// device's samples step through the level before it, then exactly, a
// least-squares line through the ramp's samples, with the uncertainty the
// samples' noise gives it. The clock tests compare
// where devices marking one host instant put it on a session's axis.
#pragma once

#include "devices/simulator/ClockMark.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace tactiscope::testing {

// Where a mark was found, and the standard uncertainty its samples' noise
// gives that place (the quiet level's scatter through the line's fit).
struct FoundMark {
    double t_s = 0.0;
    double u_s = 0.0;
};

// Where the ramp crosses the level before it: a line through the samples
// within 0.6 of its half-width of `near_s` (all of them on the ramp).
inline std::optional<FoundMark> markTime_s(const std::vector<double>& t, const std::vector<double>& values,
                                           double near_s, double halfWidth_s)
{
    double level = 0.0, levelSquares = 0.0;
    int quiet = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] > near_s - 2.0 * halfWidth_s - 0.5 && t[i] < near_s - 2.0 * halfWidth_s) {
            level += values[i];
            levelSquares += values[i] * values[i];
            ++quiet;
        }
    if (quiet < 2) return std::nullopt;
    level /= quiet;
    const double noise = std::sqrt(std::max(0.0, (levelSquares - quiet * level * level) / (quiet - 1)));
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double x = t[i] - near_s, y = values[i] - level;
        if (std::abs(x) > 0.6 * halfWidth_s) continue;
        n += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    if (n < 2.0) return std::nullopt;
    const double spread = sxx - sx * sx / n;
    const double slope = (sxy - sx * sy / n) / spread;
    const double intercept = (sy - slope * sx) / n;
    const double at = -intercept / slope;  // from near_s
    // The line's value at `at` has the noise's u through the fit; over the slope, a time.
    const double u = noise / std::abs(slope) * std::sqrt(1.0 / n + (at - sx / n) * (at - sx / n) / spread);
    return FoundMark{near_s + at, u};
}

// The first estimate: where the samples step up through their first
// value by more than a twentieth of the mark, between the two around it.
inline std::optional<double> roughMark_s(const std::vector<double>& t, const std::vector<double>& values)
{
    for (std::size_t i = 1; i + 1 < values.size(); ++i) {
        const double a = values[i] - values[0], b = values[i + 1] - values[0];
        if (a < 0.0 && b >= 0.0 && b - a > 0.05 * devices::simulator::kMarkHeight)
            return t[i] + (0.0 - a) / (b - a) * (t[i + 1] - t[i]);
    }
    return std::nullopt;
}

}  // namespace tactiscope::testing
