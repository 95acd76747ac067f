// Mean with outlier rejection as the paper does it ("all readings more than
// three standard deviations from the mean value were rejected"): once. The
// mean, σ and standard error are then those of the kept values. Repeating
// the cut until nothing more goes would trim the tails of plain Gaussian
// noise round after round (and bias σ low), which the paper does not do.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core::compliance {

struct RobustMean {
    double mean = 0.0;
    double standardDeviation = 0.0;  // of the kept values (n − 1)
    double standardError = 0.0;      // σ/√n of the kept values
    std::size_t used = 0;
    std::size_t rejected = 0;
};

// Throws std::invalid_argument for an empty input or k ≤ 0. When `kept` is
// given it receives, per value, whether the value was kept.
RobustMean robustMean(std::span<const double> values, double k = 3.0, std::vector<bool>* kept = nullptr);

}  // namespace tactiscope::core::compliance
