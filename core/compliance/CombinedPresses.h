// The presses of one specimen summed up into one reading: the mean of their
// k_o weighted by their noise (1/SE², equal weights when a press has no
// scatter), its noise standard error, and the zero's part. Presses read on
// one zero share its error, so that part does not average away: it is the
// weighted mean of the presses' zero parts — an upper bound, reached when
// all presses respond to the zero alike, and for presses on several zeros
// an overstatement rather than a claim of more than is known.
#pragma once

#include "core/compliance/StiffnessReadings.h"

#include <optional>
#include <span>

namespace tactiscope::core::compliance {

struct CombinedPresses {
    double stiffness_n_per_m = 0.0;
    double standardError_n_per_m = 0.0;
    std::optional<double> zeroUncertainty_n_per_m;
    std::size_t presses = 0;  // in range, combined

    double uncertainty_n_per_m() const;
};

// Over the presses read in range; none when there are none.
std::optional<CombinedPresses> combinePresses(std::span<const PressReading> presses);

}  // namespace tactiscope::core::compliance
