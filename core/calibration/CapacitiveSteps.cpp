// CapacitiveSteps: runs of samples → windows → the calibration's input.
#include "core/calibration/CapacitiveSteps.h"

#include "core/calibration/LinearFit.h"
#include "core/calibration/SettledCapture.h"

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace tactiscope::core::calibration {
namespace {

// Samples [first, end) of one load.
struct Run {
    std::size_t first = 0;
    std::size_t end = 0;
    double force_n = 0.0;
};

// Without a time column each row is its own time: the rows' order is all
// there is, and no drift can be measured from it.
double timeOf(const CapacitiveRecording& r, std::size_t i)
{
    return r.t_s.empty() ? static_cast<double>(i) : r.t_s[i];
}

// The statistics of samples [first, end): mean, the scatter about their
// line (the plain σ without a time column), its slope and the mean's
// standard error.
WindowStatistics windowOf(const CapacitiveRecording& r, std::size_t first, std::size_t end)
{
    WindowStatistics w;
    w.count = end - first;
    w.start_s = timeOf(r, first);
    w.end_s = timeOf(r, end - 1);
    w.stable = true;
    const std::span<const double> c(r.capacitance_f.data() + first, w.count);
    double sum = 0.0;
    for (const double v : c) sum += v;
    w.mean = sum / static_cast<double>(w.count);
    if (w.count < 2) return w;
    if (r.t_s.empty() || w.count < 3) {
        double squares = 0.0;
        for (const double v : c) squares += (v - w.mean) * (v - w.mean);
        w.sigma = std::sqrt(squares / static_cast<double>(w.count - 1));
        w.meanStandardError = w.sigma / std::sqrt(static_cast<double>(w.count));
        return w;
    }
    const LinearFit line = fitLine(std::span<const double>(r.t_s.data() + first, w.count), c);
    w.sigma = line.residualStandardDeviation;
    w.drift_per_s = line.slope;
    w.meanStandardError = meanStandardError(line.residuals);
    return w;
}

// The calibration's input from runs with known loads and their windows.
CapacitiveSteps fromRuns(const CapacitiveRecording& r, const std::vector<Run>& runs, const StabilitySettings& s)
{
    if (runs.empty() || runs.front().force_n != 0.0)
        throw std::invalid_argument("the recording must start unloaded: its first samples give C0");
    CapacitiveSteps result;
    const auto settled = [&](const Run& run) { return settledWindow(r, run.first, run.end, s); };
    const auto baseline = settled(runs.front());
    if (!baseline) throw std::invalid_argument("the unloaded baseline at the start never settles");
    result.input.baseline = *baseline;
    std::optional<double> previous;
    for (std::size_t k = 1; k < runs.size(); ++k) {
        const Run& run = runs[k];
        const bool last = k + 1 == runs.size();
        if (run.force_n == 0.0) {
            // The baseline at the end measures the drift; one between
            // weights (each placed on its own) is not a step.
            if (last)
                if (const auto final = settled(run)) {
                    result.finalShift_f = final->mean - baseline->mean;
                    if (!r.t_s.empty()) result.input.finalBaseline = *final;
                }
            continue;
        }
        const auto window = settled(run);
        if (!window) {
            ++result.unsettled;
            continue;
        }
        const bool loading = !previous || run.force_n > *previous ||
                             (run.force_n == *previous && !result.steps.empty() && result.steps.back().loading);
        previous = run.force_n;
        result.steps.push_back({run.force_n, loading, *window});
        result.input.steps.push_back(
            {run.force_n, std::nullopt, window->mean, window->middle_s(), loading, window->meanStandardError});
    }
    if (result.steps.size() < 2) throw std::invalid_argument("fewer than two load steps settled");
    return result;
}

// A stable window may end on the first sample of the next step, or begin
// on the last of the one before: one such sample barely moves a 2 s
// window's line. Samples at a plateau's edges beyond 4σ of the rest are
// those steps', not the plateau's.
void trimEdges(const CapacitiveRecording& r, Run& p)
{
    const auto off = [&](std::size_t edge, std::size_t first, std::size_t end) {
        const WindowStatistics rest = windowOf(r, first, end);
        return std::abs(r.capacitance_f[edge] - rest.mean) > 4.0 * rest.sigma;
    };
    while (p.end - p.first > 3 && off(p.end - 1, p.first, p.end - 1)) --p.end;
    while (p.end - p.first > 3 && off(p.first, p.first + 1, p.end)) ++p.first;
}

}  // namespace

std::optional<WindowStatistics> settledWindow(const CapacitiveRecording& r, std::size_t first, std::size_t end,
                                              const StabilitySettings& stability)
{
    if (end <= first) return std::nullopt;
    if (r.t_s.empty()) return windowOf(r, first, end);
    const std::span<const double> t(r.t_s.data() + first, end - first);
    const std::span<const double> c(r.capacitance_f.data() + first, end - first);
    const auto from = settledFrom(t, c, stability);
    if (!from) return std::nullopt;
    return windowOf(r, first + *from, end);
}

CapacitiveSteps stepsFromLoads(const CapacitiveRecording& r, const StabilitySettings& stability)
{
    if (r.load_n.size() != r.capacitance_f.size() || (!r.t_s.empty() && r.t_s.size() != r.capacitance_f.size()))
        throw std::invalid_argument("every sample needs its load (and its time, when timed)");
    std::vector<Run> runs;
    for (std::size_t i = 0; i < r.load_n.size(); ++i) {
        if (runs.empty() || r.load_n[i] != runs.back().force_n)
            runs.push_back({i, i + 1, r.load_n[i]});
        else
            runs.back().end = i + 1;
    }
    return fromRuns(r, runs, stability);
}

CapacitiveSteps stepsFromPlateaus(const CapacitiveRecording& r, const std::vector<double>& loads_n,
                                  const StabilitySettings& stability)
{
    if (r.t_s.size() != r.capacitance_f.size())
        throw std::invalid_argument("finding the steps by their stability needs the samples' times");
    // A plateau: consecutive samples whose window (ending there) is stable,
    // from the start of its first stable window to the end of its last.
    std::vector<Run> plateaus;
    StabilityMonitor monitor(stability);
    bool inPlateau = false;
    for (std::size_t i = 0; i < r.t_s.size(); ++i) {
        const auto w = monitor.push(r.t_s[i], r.capacitance_f[i]);
        if (w && w->stable) {
            // A stable window overlapping the last plateau is that plateau
            // again (a noise burst broke it for a moment): over shared
            // samples two stable windows are at one level. After a step,
            // no stable window reaches back across it.
            if (!inPlateau && !plateaus.empty() && w->start_s <= r.t_s[plateaus.back().end - 1]) inPlateau = true;
            if (!inPlateau) {
                std::size_t from = plateaus.empty() ? 0 : plateaus.back().end;
                while (r.t_s[from] < w->start_s) ++from;
                plateaus.push_back({from, i + 1, 0.0});
                inPlateau = true;
            }
            plateaus.back().end = i + 1;
        } else {
            inPlateau = false;
        }
    }
    for (Run& p : plateaus) trimEdges(r, p);
    if (plateaus.size() != loads_n.size())
        throw std::invalid_argument("the recording has " + std::to_string(plateaus.size()) + " stable steps, but " +
                                    std::to_string(loads_n.size()) + " loads are listed (the unloaded baseline first)");
    for (std::size_t k = 0; k < plateaus.size(); ++k) plateaus[k].force_n = loads_n[k];
    return fromRuns(r, plateaus, stability);
}

}  // namespace tactiscope::core::calibration
