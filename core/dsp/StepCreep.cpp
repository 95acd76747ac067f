// StepCreep: the steps found, the two time constants searched on a
// logarithmic grid then refined, τ_c's ± from the residuals' curvature.
#include "core/dsp/StepCreep.h"

#include "core/dsp/Median.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace tactiscope::core::dsp {
namespace {

// A step stands this many of its detector's noise σ above the level before.
constexpr double kStepSigmas = 8.0;
// Its first sample stands this many of a sample's σ off the level before.
constexpr double kOnsetSigmas = 5.0;
// A step's fit spans at least this long and holds this many samples.
constexpr double kShortestFit_s = 2.0;
constexpr std::size_t kFewestSamples = 10;
constexpr std::size_t kGridPoints = 24;
// The slow part is the creep only this many times slower than the fast.
constexpr double kApart = 3.0;

struct Step {
    std::size_t first = 0;  // its first sample after the onset
    std::size_t end = 0;    // one past its last
    double onset_s = 0.0;
    bool seen = true;  // its onset was sampled (not in a gap, where it is unknown)
};

// A sample's noise σ from the first differences (median absolute, Gaussian):
// steps and drift barely move a median.
double sampleSigma(std::span<const double> x)
{
    std::vector<double> differences;
    differences.reserve(x.size());
    for (std::size_t i = 1; i < x.size(); ++i)
        if (std::isfinite(x[i]) && std::isfinite(x[i - 1])) differences.push_back(std::fabs(x[i] - x[i - 1]));
    return median(std::move(differences)) / 0.6745 / std::sqrt(2.0);
}

double meanOf(std::span<const double> x, std::size_t from, std::size_t to)
{
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = from; i < to; ++i)
        if (std::isfinite(x[i])) sum += x[i], ++n;
    return n > 0 ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}

// The steps: where the mean of the next m present samples leaves the mean
// of the m before by kStepSigmas (present ones: a gap does not hide a step
// behind it); the onset is the sample before the first one that leaves the
// level of the second before it. Another step is looked for only
// kShortestFit_s after an onset, past the fast part's swing.
std::vector<Step> findSteps(std::span<const double> x, double rate_hz, double sigma)
{
    const auto m = static_cast<std::size_t>(std::max(2.0, std::round(0.2 * rate_hz)));
    const auto levelSamples = static_cast<std::size_t>(std::max(3.0, std::round(rate_hz)));
    const auto deadSamples = static_cast<std::size_t>(std::ceil(kShortestFit_s * rate_hz));
    const double threshold = kStepSigmas * sigma * std::sqrt(2.0 / static_cast<double>(m));
    // The present samples' places, and running sums over them: each
    // window's mean in two subtractions, however long the windows.
    std::vector<std::size_t> at;
    std::vector<double> sums{0.0};
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i])) continue;
        at.push_back(i);
        sums.push_back(sums.back() + x[i]);
    }
    const auto mean = [&](std::size_t from, std::size_t to) {  // over present samples [from, to)
        return (sums[to] - sums[from]) / static_cast<double>(to - from);
    };
    std::vector<Step> steps;
    std::size_t allowedFrom = m;  // a present sample's number
    std::size_t levelFrom = 0;
    for (std::size_t k = allowedFrom; k + m <= at.size(); ++k) {
        if (k < allowedFrom || at[k] < (steps.empty() ? 0 : steps.back().first + deadSamples)) continue;
        if (!(std::fabs(mean(k, k + m) - mean(k - m, k)) > threshold)) continue;
        // The level before it, and its first sample off that level.
        const std::size_t levelEnd = k - m;
        const std::size_t levelStart = std::max(levelFrom, levelEnd - std::min(levelEnd, levelSamples));
        if (levelStart >= levelEnd) continue;
        const double level = mean(levelStart, levelEnd);
        std::size_t moved = levelEnd;
        while (moved < k + m && !(std::fabs(x[at[moved]] - level) > kOnsetSigmas * sigma)) ++moved;
        if (moved >= k + m || at[moved] == 0) continue;
        const std::size_t first = at[moved];
        steps.push_back({first, x.size(), static_cast<double>(first - 1) / rate_hz, std::isfinite(x[first - 1])});
        if (steps.size() > 1) steps[steps.size() - 2].end = first;  // the onset's sample is the step's before
        allowedFrom = moved + 1;
        levelFrom = moved + 1;
    }
    return steps;
}

// One step's least squares for given time constants: y/σ against
// 1, (t − t0)/T, −e^{−(t−t0)/τ_f}, −e^{−(t−t0)/τ_c}.
struct StepFit {
    double rss = 0.0;
    std::array<double, 4> beta{};
    std::size_t samples = 0;
};

// What of a step's normal equations τ_f leaves alone (all but its column,
// 2): the search tries many τ_f for each τ_c, and pays for these once.
struct SlowSums {
    std::array<std::array<double, 4>, 4> normal{};
    std::array<double, 4> projected{};
    double squares = 0.0;
    double centre = 0.0;
    std::size_t samples = 0;
};

double stepLength_s(const Step& step, double rate_hz)
{
    return static_cast<double>(step.end - step.first + 1) / rate_hz;
}

SlowSums slowSums(std::span<const double> x, const Step& step, double rate_hz, double sigma, double slow_s)
{
    SlowSums sums;
    sums.centre = meanOf(x, step.first, step.end);
    if (!std::isfinite(sums.centre)) return sums;
    const double length_s = stepLength_s(step, rate_hz);
    // e^{−t/τ} sample by sample as powers of one factor: no exp per sample.
    const double factor = std::exp(-1.0 / (rate_hz * slow_s));
    double slow = 1.0;
    for (std::size_t i = step.first; i < step.end; ++i) {
        slow *= factor;
        if (!std::isfinite(x[i])) continue;
        const double t = static_cast<double>(i) / rate_hz - step.onset_s;
        const std::array<double, 4> row{1.0, t / length_s, 0.0, -slow};
        const double y = (x[i] - sums.centre) / sigma;
        for (const std::size_t r : {0u, 1u, 3u}) {
            for (const std::size_t c : {0u, 1u, 3u}) sums.normal[r][c] += row[r] * row[c];
            sums.projected[r] += row[r] * y;
        }
        sums.squares += y * y;
        ++sums.samples;
    }
    return sums;
}

// The step's fit with τ_f's column added to the sums (τ_c the sums').
StepFit fitStep(std::span<const double> x, const Step& step, double rate_hz, double sigma, double fast_s, double slow_s,
                const SlowSums& sums)
{
    StepFit fit;
    fit.samples = sums.samples;
    if (sums.samples == 0) return fit;
    auto normal = sums.normal;
    auto projected = sums.projected;
    const double length_s = stepLength_s(step, rate_hz);
    const double fastFactor = std::exp(-1.0 / (rate_hz * fast_s));
    const double slowFactor = std::exp(-1.0 / (rate_hz * slow_s));
    double fast = 1.0, slow = 1.0;
    for (std::size_t i = step.first; i < step.end; ++i) {
        fast *= fastFactor;
        slow *= slowFactor;
        if (!std::isfinite(x[i])) continue;
        const double t = static_cast<double>(i) / rate_hz - step.onset_s;
        const double y = (x[i] - sums.centre) / sigma;
        normal[2][0] -= fast;
        normal[2][1] -= fast * t / length_s;
        normal[2][2] += fast * fast;
        normal[2][3] += fast * slow;
        projected[2] -= fast * y;
    }
    for (const std::size_t c : {0u, 1u, 3u}) normal[c][2] = normal[2][c];
    // Gauss–Jordan with the pivots' columns kept: a column that the others
    // already span (an exponential flat over the step) is left at zero.
    auto a = normal;
    auto b = projected;
    std::array<bool, 4> used{};
    for (std::size_t c = 0; c < 4; ++c) {
        const double scale = normal[c][c];
        if (!(scale > 0.0) || !(std::fabs(a[c][c]) > 1e-10 * scale)) continue;
        used[c] = true;
        for (std::size_t r = 0; r < 4; ++r) {
            if (r == c) continue;
            const double factor = a[r][c] / a[c][c];
            for (std::size_t k = 0; k < 4; ++k) a[r][k] -= factor * a[c][k];
            b[r] -= factor * b[c];
        }
    }
    double explained = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
        if (!used[c]) continue;
        fit.beta[c] = b[c] / a[c][c];
        explained += fit.beta[c] * projected[c];
    }
    fit.rss = std::max(0.0, sums.squares - explained);
    return fit;
}

struct Search {
    std::span<const double> x;
    const std::vector<Step>& steps;
    double rate_hz;
    double sigma;

    std::vector<SlowSums> slowAt(double slow_s) const
    {
        std::vector<SlowSums> sums;
        for (const Step& step : steps) sums.push_back(slowSums(x, step, rate_hz, sigma, slow_s));
        return sums;
    }
    std::vector<StepFit> fits(double fast_s, double slow_s, const std::vector<SlowSums>& sums) const
    {
        std::vector<StepFit> fitted;
        for (std::size_t j = 0; j < steps.size(); ++j)
            fitted.push_back(fitStep(x, steps[j], rate_hz, sigma, fast_s, slow_s, sums[j]));
        return fitted;
    }
    double rss(double fast_s, double slow_s, const std::vector<SlowSums>& sums) const
    {
        double total = 0.0;
        for (std::size_t j = 0; j < steps.size(); ++j)
            total += fitStep(x, steps[j], rate_hz, sigma, fast_s, slow_s, sums[j]).rss;
        return total;
    }
    // The fast constant that fits best with `slow_s`, within [low, high].
    double bestFast(double slow_s, const std::vector<SlowSums>& sums, double low, double high) const
    {
        high = std::min(high, slow_s / 1.5);
        if (!(high > low)) return low;
        double a = std::log(low), b = std::log(high);
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        double c = b - g * (b - a), d = a + g * (b - a);
        double fc = rss(std::exp(c), slow_s, sums), fd = rss(std::exp(d), slow_s, sums);
        for (int k = 0; k < 40 && b - a > 1e-3; ++k) {
            if (fc < fd) {
                b = d, d = c, fd = fc;
                c = b - g * (b - a), fc = rss(std::exp(c), slow_s, sums);
            } else {
                a = c, c = d, fc = fd;
                d = a + g * (b - a), fd = rss(std::exp(d), slow_s, sums);
            }
        }
        return std::exp((a + b) / 2.0);
    }
};

// The creep's share, A_c = f·(A_f + A_c) through the steps by least
// squares, and from three steps on the ± their scatter about it gives.
struct Share {
    std::optional<double> fraction;
    std::optional<double> scatterU;
};

Share shareOf(const std::vector<StepFit>& fits)
{
    double sxy = 0.0, sxx = 0.0;
    for (const StepFit& fit : fits) {
        const double step = fit.beta[2] + fit.beta[3];
        sxy += fit.beta[3] * step;
        sxx += step * step;
    }
    Share share;
    if (!(sxx > 0.0)) return share;
    share.fraction = sxy / sxx;
    if (fits.size() < 3) return share;
    double scatter = 0.0;
    for (const StepFit& fit : fits) {
        const double r = fit.beta[3] - *share.fraction * (fit.beta[2] + fit.beta[3]);
        scatter += r * r;
    }
    share.scatterU = std::sqrt(scatter / static_cast<double>(fits.size() - 1) / sxx);
    return share;
}

}  // namespace

std::optional<StepCreep> findStepCreep(std::span<const double> values, double rate_hz)
{
    if (!(rate_hz > 0.0) || values.size() < kFewestSamples) return std::nullopt;
    const double sigma = sampleSigma(values);
    if (!(sigma > 0.0)) return std::nullopt;
    std::vector<Step> steps;
    for (const Step& step : findSteps(values, rate_hz, sigma)) {
        const std::size_t n = step.end - step.first;
        // A step whose onset fell in a gap is not fitted: where it began is unknown.
        if (step.seen && n >= kFewestSamples && static_cast<double>(n) / rate_hz >= kShortestFit_s)
            steps.push_back(step);
    }
    if (steps.empty()) return std::nullopt;
    std::vector<double> lengths;
    for (const Step& step : steps) lengths.push_back(static_cast<double>(step.end - step.first) / rate_hz);
    // τ_f from half a sample to a third of a step; τ_c up to a step's
    // length, beyond which it is the drift's line.
    const double lowest = 0.5 / rate_hz;
    const double longest = median(lengths);
    const Search search{values, steps, rate_hz, sigma};
    // The residuals are steep in τ_f (a step is many σ): τ_c on a grid, and
    // for each the τ_f that fits it best, found by golden section.
    const double fastHigh = longest / 3.0;
    const auto profile = [&](double slow) {
        const auto sums = search.slowAt(slow);
        return search.rss(search.bestFast(slow, sums, lowest, fastHigh), slow, sums);
    };
    const double slowest = 3.0 * lowest;
    const auto grid = [&](std::size_t k) {
        return slowest * std::pow(longest / slowest, static_cast<double>(k) / (kGridPoints - 1));
    };
    double best = INFINITY;
    std::size_t bestK = 0;
    for (std::size_t k = 0; k < kGridPoints; ++k) {
        const double r = profile(grid(k));
        if (r < best) best = r, bestK = k;
    }
    if (bestK == 0 || bestK + 1 >= kGridPoints) return std::nullopt;  // at a bound: not told from the noise
    // Refined by golden section over the grid's cells beside it.
    double a = std::log(grid(bestK - 1)), b = std::log(grid(bestK + 1));
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = profile(std::exp(c)), fd = profile(std::exp(d));
    for (int k = 0; k < 40 && b - a > 1e-4; ++k) {
        if (fc < fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a), fc = profile(std::exp(c));
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a), fd = profile(std::exp(d));
        }
    }
    const double bestSlow = std::exp((a + b) / 2.0);
    const auto bestSums = search.slowAt(bestSlow);
    const double bestFastAt = search.bestFast(bestSlow, bestSums, lowest, fastHigh);
    best = search.rss(bestFastAt, bestSlow, bestSums);

    // Each step's fit where the two constants are (τ_f the best for τ_c).
    const auto fitsAt = [&](double slow) {
        const auto sums = search.slowAt(slow);
        return search.fits(search.bestFast(slow, sums, lowest, fastHigh), slow, sums);
    };
    const std::vector<StepFit> fits = fitsAt(bestSlow);
    std::size_t samples = 0;
    for (const StepFit& fit : fits) samples += fit.samples;
    const std::size_t parameters = 4 * steps.size() + 2;
    if (samples <= parameters) return std::nullopt;
    // τ_c's ±: where the profile rises by one residual variance (Δχ² = 1),
    // from its curvature at the minimum.
    const double variance = best / static_cast<double>(samples - parameters);
    const double h = 0.05 * bestSlow;
    const double curvature = (profile(bestSlow + h) - 2.0 * best + profile(bestSlow - h)) / (h * h);
    if (!(curvature > 0.0)) return std::nullopt;

    StepCreep creep;
    creep.steps = steps.size();
    creep.timeConstant_s = bestSlow;
    creep.timeConstantU_s = std::sqrt(2.0 * variance / curvature);
    creep.settleTime_s = bestFastAt;
    const Share share = shareOf(fits);
    if (!share.fraction) return std::nullopt;
    creep.fraction = *share.fraction;
    // Its ±: the steps' scatter about it, and τ_c's ± carried through (a
    // slower creep is a larger one at the onset).
    if (share.scatterU) {
        const auto above = shareOf(fitsAt(bestSlow + h)).fraction, below = shareOf(fitsAt(bestSlow - h)).fraction;
        const double slope = above && below ? (*above - *below) / (2.0 * h) : 0.0;
        creep.fractionU = std::hypot(*share.scatterU, slope * creep.timeConstantU_s);
    }
    // A creep the noise could have drawn is none: two parts not told apart,
    // a share within twice its ±, a time constant known to no better than
    // half. Nor is a slow part of most of the step: that is the beam
    // settling, and the fast one a ripple of the noise.
    if (creep.timeConstant_s < kApart * creep.settleTime_s || !(std::fabs(creep.fraction) < 0.5)) return std::nullopt;
    if (creep.fractionU && !(std::fabs(creep.fraction) > 2.0 * *creep.fractionU)) return std::nullopt;
    if (!(creep.timeConstantU_s < 0.5 * creep.timeConstant_s)) return std::nullopt;
    return creep;
}

}  // namespace tactiscope::core::dsp
