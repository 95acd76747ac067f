// Splitting a series at its missing samples.
#include "core/dsp/GapFreeStretches.h"

#include <cmath>

namespace tactiscope::core::dsp {

std::vector<Stretch> gapFreeStretches(std::span<const double> values, std::size_t least)
{
    std::vector<Stretch> stretches;
    std::size_t i = 0;
    while (i < values.size()) {
        while (i < values.size() && !std::isfinite(values[i])) ++i;
        const std::size_t first = i;
        while (i < values.size() && std::isfinite(values[i])) ++i;
        if (i > first && i - first >= least) stretches.push_back({first, i - first});
    }
    return stretches;
}

}  // namespace tactiscope::core::dsp
