// CapacitiveSweep: a reference-force sweep → baselines, directions, bins →
// the calibration's input.
#include "core/calibration/CapacitiveSweep.h"

#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

namespace tactiscope::core::calibration {
namespace {

double meanOf(std::span<const double> values)
{
    double sum = 0.0;
    for (const double v : values) sum += v;
    return sum / static_cast<double>(values.size());
}

// Where the sweep turns: the extreme before each rise or fall of `turn`
// past it.
std::vector<std::size_t> turningPoints(std::span<const double> force, double turn)
{
    std::vector<std::size_t> turns;
    bool rising = true;
    std::size_t extreme = 0;
    for (std::size_t i = 1; i < force.size(); ++i) {
        if (rising ? force[i] > force[extreme] : force[i] < force[extreme]) {
            extreme = i;
        } else if (std::abs(force[i] - force[extreme]) > turn) {
            turns.push_back(extreme);
            rising = !rising;
            extreme = i;
        }
    }
    return turns;
}

// The force a beam that settles as a first-order lag of time constant
// `tau` feels, sample by sample (tau 0: the force itself).
std::vector<double> felt(std::span<const double> t, std::span<const double> force, double tau)
{
    std::vector<double> out(force.begin(), force.end());
    if (!(tau > 0.0)) return out;
    for (std::size_t i = 1; i < out.size(); ++i)
        out[i] = out[i - 1] + (force[i] - out[i - 1]) * (1.0 - std::exp(-(t[i] - t[i - 1]) / tau));
    return out;
}

// The scatter of the samples [begin, end) about one straight line of
// capacitance against force: a lag left in spreads loading and unloading
// apart, so the right one makes it least.
double scatterAboutLine(std::span<const double> force, std::span<const double> c, std::size_t begin, std::size_t end)
{
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;
    const double c0 = c[begin];  // (centred: farads are tiny next to their sums of squares)
    for (std::size_t i = begin; i < end; ++i) {
        const double x = force[i], y = c[i] - c0;
        n += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
    }
    if (n < 3.0) return std::numeric_limits<double>::infinity();
    const double vx = sxx - sx * sx / n, vxy = sxy - sx * sy / n, vy = syy - sy * sy / n;
    return vx > 0.0 ? (vy - vxy * vxy / vx) / n : std::numeric_limits<double>::infinity();
}

// The beam's time constant within [0, most]: a grid of 20 ms, then of
// 1 ms about its best.
double lagOf(std::span<const double> t, std::span<const double> c, std::span<const double> force, std::size_t begin,
             std::size_t end, double most)
{
    double best = 0.0;
    double least = scatterAboutLine(force, c, begin, end);
    for (const double step : {0.02, 0.001}) {
        const double from = step == 0.02 ? step : std::max(step, best - 0.02);
        const double to = step == 0.02 ? most : best + 0.02;
        for (double tau = from; tau <= to + step / 2; tau += step) {
            const double scatter = scatterAboutLine(felt(t, force, tau), c, begin, end);
            if (scatter < least) {
                least = scatter;
                best = tau;
            }
        }
    }
    return best;
}

}  // namespace

SweepSteps stepsFromSweep(const CapacitiveRecording& r, const SweepSettings& settings)
{
    const std::size_t n = r.capacitance_f.size();
    if (r.t_s.size() != n || r.load_n.size() != n)
        throw std::invalid_argument("a sweep needs every sample's time and reference force");
    if (settings.bins < 1 || settings.minimumPerBin < 2)
        throw std::invalid_argument("a sweep needs at least one bin of two samples");
    const auto [lowest, highest] = std::ranges::minmax(r.load_n);
    if (!(highest > lowest)) throw std::invalid_argument("the reference force does not change: there is no sweep");

    // The unloaded start: before the reference first leaves the bottom of
    // its range. Its first half gives the reference's zero and noise; the
    // sweep begins where the reference leaves that noise (5σ), so the
    // baseline holds no sample of the rise.
    const double unloaded = lowest + settings.unloadedFraction * (highest - lowest);
    const auto firstLoaded = std::ranges::find_if(r.load_n, [&](double f) { return f > unloaded; });
    const auto rise = static_cast<std::size_t>(firstLoaded - r.load_n.begin());
    if (rise < 4) throw std::invalid_argument("the recording must start unloaded: its first samples give C0");
    const std::span<const double> quiet(r.load_n.data(), rise / 2);
    SweepSteps result;
    result.referenceZero_n = meanOf(quiet);
    double squares = 0.0;
    for (const double f : quiet) squares += (f - result.referenceZero_n) * (f - result.referenceZero_n);
    const double noise = std::sqrt(squares / static_cast<double>(quiet.size() - 1));
    const double leaves = std::max(5.0 * noise, 1e-3 * (highest - lowest));
    std::vector<double> force(n);
    for (std::size_t i = 0; i < n; ++i) force[i] = r.load_n[i] - result.referenceZero_n;
    std::size_t begin = 0;
    while (begin < rise && force[begin] <= leaves) ++begin;
    std::size_t end = n;
    while (end > begin && force[end - 1] <= leaves) --end;

    CapacitiveSteps& out = result.steps;
    const auto baseline = settledWindow(r, 0, begin, settings.stability);
    if (!baseline) throw std::invalid_argument("the unloaded baseline before the sweep never settles");
    out.input.baseline = *baseline;
    if (const auto final = settledWindow(r, end, n, settings.stability)) {
        out.input.finalBaseline = *final;
        out.finalShift_f = final->mean - baseline->mean;
    }

    // The force each sample felt: the reference's, through the beam's lag,
    // searched with the baseline's drift taken out (left in, it tilts one
    // direction against the other as a lag does: 0.439 s was found for a
    // 0.400 s beam, and 0.5 % of hysteresis left on a beam with none).
    if (settings.maxLag_s > 0.0) {
        std::vector<double> level = r.capacitance_f;
        if (out.input.finalBaseline) {
            const double t0 = out.input.baseline.middle_s(), t1 = out.input.finalBaseline->middle_s();
            const double drift = (out.input.finalBaseline->mean - out.input.baseline.mean) / (t1 - t0);
            for (std::size_t i = 0; i < n; ++i) level[i] -= drift * (r.t_s[i] - t0);
        }
        result.lag_s = lagOf(r.t_s, level, force, begin, end, settings.maxLag_s);
    }
    const std::vector<double> feltForce = felt(r.t_s, force, result.lag_s);
    const std::span<const double> loaded(feltForce.data() + begin, end - begin);
    result.span_n = *std::ranges::max_element(std::span<const double>(force.data() + begin, end - begin));
    const std::vector<std::size_t> turns = turningPoints(loaded, settings.turnFraction * result.span_n);
    result.turns = turns.size();
    // The bins span what the beam felt (a lag rounds the peak off).
    const double width = *std::ranges::max_element(loaded) / static_cast<double>(settings.bins);
    // Each direction's samples by bin: loading until the first turn, then
    // each turn swaps.
    std::vector<std::vector<std::size_t>> bins(2 * settings.bins);
    std::size_t turn = 0;
    for (std::size_t i = 0; i < loaded.size(); ++i) {
        while (turn < turns.size() && turns[turn] < i) ++turn;
        const bool loading = turn % 2 == 0;
        const auto bin = std::min(settings.bins - 1, static_cast<std::size_t>(std::max(0.0, loaded[i]) / width));
        bins[(loading ? 0 : settings.bins) + bin].push_back(begin + i);
    }
    for (std::size_t b = 0; b < bins.size(); ++b) {
        const bool loading = b < settings.bins;
        // Loading upwards, unloading downwards, as weights go on and off.
        const std::size_t k = loading ? b : 2 * settings.bins - 1 - b;
        const auto& members = bins[loading ? k : settings.bins + k];
        if (members.size() < settings.minimumPerBin) continue;
        std::vector<double> f, c, t;
        for (const std::size_t i : members) {
            f.push_back(feltForce[i]);
            c.push_back(r.capacitance_f[i]);
            t.push_back(r.t_s[i]);
        }
        // A bin the sweep crossed gives its capacitance at its middle; one
        // it dwelt in (a quarter of its width or less), its mean at its
        // mean force.
        const auto [least, most] = std::ranges::minmax(f);
        const bool crossed = most - least > 0.25 * width;
        const LinearFit line = crossed ? fitLine(f, c) : LinearFit{};
        const double middle = crossed ? (static_cast<double>(k) + 0.5) * width : meanOf(f);
        FoundStep step;
        step.force_n = middle;
        step.loading = loading;
        step.window.mean = crossed ? line.intercept + line.slope * middle : meanOf(c);
        step.window.sigma = line.residualStandardDeviation;
        std::vector<double> residuals(c.size());
        for (std::size_t i = 0; i < c.size(); ++i)
            residuals[i] = c[i] - (crossed ? line.intercept + line.slope * f[i] : step.window.mean);
        step.window.meanStandardError = meanStandardError(residuals);
        step.window.count = members.size();
        step.window.start_s = *std::ranges::min_element(t);
        step.window.end_s = *std::ranges::max_element(t);
        step.window.stable = true;
        result.samplesUsed += members.size();
        out.steps.push_back(step);
        out.input.steps.push_back(
            {middle, std::nullopt, step.window.mean, meanOf(t), loading, step.window.meanStandardError});
    }
    if (out.steps.size() < 2) throw std::invalid_argument("the sweep gave fewer than two points");
    return result;
}

}  // namespace tactiscope::core::calibration
