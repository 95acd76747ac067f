// The presses of one specimen summed up into one reading: the mean of their
// k_o weighted by their noise (1/SE², equal weights when a press has no
// scatter), its noise standard error, and the zero's part. Presses read on
// one zero share its error, so that part does not average away: it is the
// weighted mean of the presses' zero parts — an upper bound, reached when
// all presses respond to the zero alike, and for presses on several zeros
// an overstatement rather than a claim of more than is known.
//
// Whether the presses agree: the Birge ratio R = √(χ²/(n − 1)) of their
// values about the mean, each with its own combined uncertainty. Presses
// that agree give R ≈ 1 (its spread is about 1/√(2(n − 1))); R beyond
// 1 + 3/√(2(n − 1)) says they do not — a press off the site, a changed zero
// — and the noise part of the reading's uncertainty is then scaled by R, so
// the ± covers the scatter that is there.
#pragma once

#include "core/compliance/StiffnessReadings.h"

#include <optional>
#include <span>

namespace tactiscope::core::compliance {

struct CombinedPresses {
    double stiffness_n_per_m = 0.0;
    double standardError_n_per_m = 0.0;
    std::optional<double> zeroUncertainty_n_per_m;
    std::size_t presses = 0;           // in range, combined
    std::optional<double> birgeRatio;  // two presses or more, each with an uncertainty
    bool consistent = true;            // R within its limit (standardError scaled by R when not)

    double uncertainty_n_per_m() const;
};

// Over the presses read in range; none when there are none.
std::optional<CombinedPresses> combinePresses(std::span<const PressReading> presses);

}  // namespace tactiscope::core::compliance
