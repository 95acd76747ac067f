// Parameters of the partial-correlation surface-deflection detector of
// seed 000 (section II.B), with the paper's settings as defaults:
// Δt = 2 ms, lags c = 2…150 ms in 2 ms steps, λ = c, ε = 7·10⁻⁶, threshold 0.85.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace tactiscope::core::detector {

enum class LambdaRule {
    EqualsLag,  // λ = c for each lag (the paper's choice)
    Fixed,      // one λ for every lag
};

// The cantilever spacing of the paper's prototype (15 mm), which turns the
// detector's lag into a scan speed: the default wherever a panel probe's
// own is not given (live, `analyze`, the review's re-analysis), so their
// events can be placed along the stroke (DefectSites.h).
inline constexpr double kPrototypeSpacing_m = 0.015;

struct DetectorParameters {
    double sampleInterval_s = 0.002;
    std::vector<double> lags_s = defaultLags_s();
    LambdaRule lambdaRule = LambdaRule::EqualsLag;
    double fixedLambda_s = 0.1;  // used with LambdaRule::Fixed
    // Regularisation, in the unit of a and b (dimensionless strain): adds
    // (1−r)·ε²·I₄ to the second moment every sample (eq. 9).
    double epsilon = 7e-6;
    double threshold = 0.85;
    // Gauges mounted face to face: b is negated (paper, after eq. 5).
    bool faceToFace = false;
    // When set, the sliding-window form (eqs 1–5) over this window replaces
    // exponential weighting.
    std::optional<double> window_s;

    static std::vector<double> defaultLags_s();
};

// Lags from start to stop inclusive in steps of step, all in seconds; the
// stop is included when it lies within 1e-9 s of a step. Throws
// std::invalid_argument when start or step is not positive or stop < start.
std::vector<double> lagRange_s(double start_s, double stop_s, double step_s);
// The paper's lags (2–150 ms in 2 ms steps) assume 500 Hz; a slower stream
// starts at one sample interval and steps by it, up to 150 ms. Throws
// std::invalid_argument for a rate too slow to give a lag under 150 ms.
std::vector<double> liveLags_s(double sampleRate_hz);

// The shortest recording the detector can judge a panel on: its longest
// lag (the first moment it can correlate every lag) plus three of that
// lag's forgetting times λ (after which the weighted moments hold less
// than 5 % of their start), or plus the window in the sliding-window form.
// At the paper's settings: 0.15 + 3 × 0.15 = 0.6 s. A shorter recording
// gets no automatic verdict: its silence says nothing of the panel.
double shortestJudged_s(const DetectorParameters& parameters);

// The parameters in samples, checked. A lag c becomes k = round(c/Δt) samples;
// lags that round to the same k are kept once, in increasing order. The
// window becomes round(h/Δt) samples.
struct ResolvedParameters {
    std::vector<std::uint32_t> lags;  // k, strictly increasing, ≥ 1
    std::vector<double> forgetting;   // r = exp(−Δt/λ) per lag
    std::uint32_t window = 0;         // sliding-window length in samples; 0 = exponential form
    double epsilonSquared = 0.0;
    double threshold = 0.0;
    double bSign = 1.0;  // −1 for face-to-face gauges
    double sampleInterval_s = 0.0;

    std::uint32_t maxLag() const { return lags.back(); }
};

// Throws std::invalid_argument with a message naming the bad parameter.
ResolvedParameters resolve(const DetectorParameters& parameters);

}  // namespace tactiscope::core::detector
