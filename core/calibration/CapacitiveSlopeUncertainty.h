// The capacitive beam's sensitivity ± (seed 002), propagated from what
// each point carries instead of read from the points' scatter alone.
//
// The slope is the ordinary least-squares line through the baseline's zero
// point and the steps' ΔC. Each step's ΔC is its window's mean less the
// baseline at its time, the line between the first and the final baseline,
// so its error is the step's own noise, the two baselines' noise weighted
// by where the step lies between them, and the baseline's wander about
// that line (a random walk tied to both baselines: a Brownian bridge, whose
// errors at two steps are correlated). Their covariance V gives the
// slope's variance aᵀ·V·a through the least-squares weights a.
//
// Why not the scatter: over an up-then-down protocol a wandering baseline
// looks like a load-proportional signal the scatter about the line cannot
// show (it covered 48 % of runs at ±u), while with white noise alone the
// settling's tail inflated the scatter (88 %). The wander cannot be seen in
// a recording whose noise is far above it over a window, so it is a Type B
// input: the beam's baseline stability, σ_w in F/√s.
//
// What the model leaves out (the silicone's creep, a hysteresis, a step
// taken too early) shows as residuals beyond what V allows: when their χ²
// passes its 99th percentile, the ± is widened by the Birge ratio, and the
// result says so.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace tactiscope::core::calibration {

struct SlopePoint {
    double force_n = 0.0;
    double residual_f = 0.0;  // off the fitted line
    double u_f = 0.0;         // its window mean's standard uncertainty
    double t_s = 0.0;
};

struct BaselineReading {
    double t_s = 0.0;
    double u_f = 0.0;  // its mean's standard uncertainty
};

struct SlopeUncertaintyInput {
    std::vector<SlopePoint> steps;  // the baseline's zero point is implied
    BaselineReading first;
    std::optional<BaselineReading> final;       // the drift's line runs through both
    std::optional<double> wander_f_per_sqrt_s;  // the baseline's random walk
};

struct SlopeUncertainty {
    double u_f_per_n = 0.0;
    double chiSquarePerDegree = 0.0;  // of the residuals against V
    bool widened = false;             // by the Birge ratio: the points scatter beyond V
};

// None when a step's u is not known (0): the scatter is all there is then.
std::optional<SlopeUncertainty> propagatedSlopeUncertainty(const SlopeUncertaintyInput& input);

}  // namespace tactiscope::core::calibration
