// The statistic the benchmarks report beside the median: interference on a
// shared machine only ever adds time, so the fastest repetition is the best
// estimate of what the code costs.
#pragma once

#include <algorithm>
#include <vector>

namespace tactiscope::bench {

inline double fastest(const std::vector<double>& v)
{
    return *std::min_element(v.begin(), v.end());
}

}  // namespace tactiscope::bench
