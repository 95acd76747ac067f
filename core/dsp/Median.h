// The median of a sample (the upper middle of an even one), NaN of an
// empty one: the robust level the spectrum's lines and floors stand above.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace tactiscope::core::dsp {

inline double median(std::vector<double> values)
{
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace tactiscope::core::dsp
