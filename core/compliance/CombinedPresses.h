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
//
// A session whose presses include bounds (a ratio within 2u of Q = 1 or of
// Q = k_h/k_l) is at the probe's edge: the few presses read in range there
// are those the noise pushed inside, and their mean is a bias (10⁸ N/m read
// as 6·10⁶ ± 2·10⁶ beside presses saying > 7.8·10⁶). Its presses are then
// combined as ratios, the bounded ones too, the same way (weights of their
// ratios' noise, the zero's part a weighted mean, the Birge ratio), and the
// session is a bound: k_o at 2u from the mean ratio towards the inside, the
// way most of its presses' bounds point. Never a number: taken as one where
// the mean ratio lay 2u inside, 5 of 11 such sessions at 10⁸ N/m missed
// the truth by their 95 % limits (the noise had pushed them inside).
#pragma once

#include "core/compliance/StiffnessReadings.h"

#include <optional>
#include <span>

namespace tactiscope::core::compliance {

struct CombinedPresses {
    // Ok: a number. BelowRange/AboveRange: the presses together lie within
    // 2u of a limit of the probe; bound_n_per_m is then what they are below
    // or above (none when that is the limit itself).
    PressStatus status = PressStatus::Ok;
    std::optional<double> bound_n_per_m;
    double stiffness_n_per_m = 0.0;
    double standardError_n_per_m = 0.0;
    std::optional<double> zeroUncertainty_n_per_m;
    std::size_t presses = 0;           // in range, combined
    std::optional<double> birgeRatio;  // two presses or more, each with an uncertainty
    bool consistent = true;            // R within its limit (standardError scaled by R when not)
    // k_o at the mean ratio ∓ 2u through the exact map (when Ok): limits of
    // about 95 %, asymmetric near the probe's ends.
    double lowerLimit_n_per_m = 0.0;
    double upperLimit_n_per_m = 0.0;

    double uncertainty_n_per_m() const;
};

// Over the presses read in range, or, when some are bounds, over all that
// are not clipped (a bound); none when no press is read or bounded.
std::optional<CombinedPresses> combinePresses(const sensors::CompliancePair& pair,
                                              std::span<const PressReading> presses);

}  // namespace tactiscope::core::compliance
