// The gap-free stretches of a series whose missing samples are NaN (a
// stored channel reads a gap as NaN): where a spectrum may take segments
// and a zero-phase filter may run, never across a gap.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core::dsp {

struct Stretch {
    std::size_t first = 0;
    std::size_t count = 0;
};

// In order; stretches of fewer than `least` samples are left out.
std::vector<Stretch> gapFreeStretches(std::span<const double> values, std::size_t least = 1);

}  // namespace tactiscope::core::dsp
