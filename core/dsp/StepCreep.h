// A capacitive beam's creep after a load step (issue 57, seed 002): the
// soft silicone answers a weight in two parts, the beam swinging to rest
// (fast) and the viscoelastic creep (slow), so after a step at t0 the
// channel reads
//
//     y(t) = a + b·(t − t0) − A_f·e^{−(t−t0)/τ_f} − A_c·e^{−(t−t0)/τ_c}
//
// (a the level it settles to, b the baseline's drift over the step). The
// steps are found in the recording (a jump of many noise σ), each fitted
// from its onset to the next, the two time constants shared by all steps
// and the four linear parameters each step's own (separable least
// squares). What it gives: τ_c with its standard uncertainty from the
// profile of the residuals in τ_c (white noise assumed: the fit's σ is the
// residuals'), and the creep's share of the step, A_c / (A_f + A_c),
// pooled over the steps with its ± from their scatter.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace tactiscope::core::dsp {

struct StepCreep {
    std::size_t steps = 0;            // steps fitted
    double timeConstant_s = 0.0;      // τ_c
    double timeConstantU_s = 0.0;     // its standard uncertainty (k = 1)
    double settleTime_s = 0.0;        // τ_f, the fast part's
    double fraction = 0.0;            // A_c / (A_f + A_c), pooled
    std::optional<double> fractionU;  // k = 1, from three steps on
};

// Samples at `sampleRate_hz` (NaN where missing). None without a step
// fitted (one standing 8 σ out of the noise, with 2 s and 10 samples after
// it before the next, whose onset is not in a gap), or when the creep cannot be told from the noise:
// its time constant at the search's bounds, under three times the fast
// part's or known to no better than half, or its share within twice its
// ± (or half the step or more: that is the beam settling).
std::optional<StepCreep> findStepCreep(std::span<const double> values, double sampleRate_hz);

}  // namespace tactiscope::core::dsp
