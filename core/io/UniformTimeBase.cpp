// Uniform time-base check.
#include "core/io/UniformTimeBase.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace tactiscope::core::io {

double uniformSampleInterval(std::span<const double> t, double tolerance)
{
    if (t.size() < 2) throw TimeBaseError("at least two samples are needed to know the sampling interval", 0);
    std::vector<double> steps(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i) {
        steps[i - 1] = t[i] - t[i - 1];
        if (!(steps[i - 1] > 0.0)) throw TimeBaseError("time is not increasing", i);
    }
    // The median step is the reference: one odd step cannot move it, so the
    // error names the line that is actually wrong.
    std::vector<double> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double typical = sorted[sorted.size() / 2];
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (std::abs(steps[i] - typical) > tolerance * typical) {
            throw TimeBaseError("time is irregular: step of " + std::to_string(steps[i]) + " s where " +
                                    std::to_string(typical) + " s is expected",
                                i + 1);
        }
    }
    // The mean over the whole record is the most precise interval.
    return (t.back() - t.front()) / static_cast<double>(t.size() - 1);
}

}  // namespace tactiscope::core::io
