// Offline detection: lag subsets on worker threads, merged per sample.
#include "core/detector/OfflineDetection.h"

#include "core/detector/EventSegmenter.h"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace tactiscope::core::detector {
namespace {

// Outputs of every pair for one lag subset.
using PairSeries = std::vector<std::vector<DetectorOutput>>;

PairSeries runSubset(const SeriesInput& input, const DetectorParameters& parameters)
{
    const std::size_t pairs = input.cantilevers.size() - 1;
    PairSeries out(pairs);
    for (std::size_t p = 0; p < pairs; ++p) {
        PairDetector detector(parameters);
        out[p].resize(input.cantilevers[p].size());
        detector.process(input.cantilevers[p], input.cantilevers[p + 1], out[p]);
    }
    return out;
}

// Larger R wins; on equal R the earlier pair, then the shorter lag, exactly
// as one ProbeDetector over all lags would choose.
bool better(double r, std::size_t pair, std::uint32_t lag, double bestR, std::size_t bestPair, std::uint32_t bestLag)
{
    if (r != bestR) return r > bestR;
    return pair != bestPair ? pair < bestPair : lag < bestLag;
}

}  // namespace

std::vector<ProbeOutput> detectSeries(const SeriesInput& input, const DetectorParameters& parameters, unsigned threads)
{
    if (input.cantilevers.size() < 2) throw std::invalid_argument("a probe needs at least two cantilevers");
    const std::size_t n = input.cantilevers.front().size();
    for (const auto& series : input.cantilevers) {
        if (series.size() != n) throw std::invalid_argument("cantilever series differ in length");
    }
    if (!input.times.empty() && input.times.size() != n)
        throw std::invalid_argument("times and cantilever series differ in length");
    const ResolvedParameters resolved = resolve(parameters);

    // Lag subsets of whole groups of 8, so every thread keeps its vectors full.
    const std::size_t groups = (resolved.lags.size() + kLaneWidth - 1) / kLaneWidth;
    const std::size_t workers = std::max<std::size_t>(1, std::min<std::size_t>(threads, groups));
    std::vector<DetectorParameters> subsets;
    for (std::size_t w = 0; w < workers; ++w) {
        const std::size_t first = groups * w / workers * kLaneWidth;
        const std::size_t last = std::min(resolved.lags.size(), groups * (w + 1) / workers * kLaneWidth);
        DetectorParameters subset = parameters;
        subset.lags_s.clear();
        for (std::size_t i = first; i < last; ++i)
            subset.lags_s.push_back(static_cast<double>(resolved.lags[i]) * parameters.sampleInterval_s);
        subsets.push_back(std::move(subset));
    }

    std::vector<PairSeries> results(workers);
    if (workers == 1) {
        results[0] = runSubset(input, subsets[0]);
    } else {
        std::vector<std::jthread> pool;
        for (std::size_t w = 0; w < workers; ++w)
            pool.emplace_back([&, w] { results[w] = runSubset(input, subsets[w]); });
    }

    std::vector<ProbeOutput> outputs(n);
    const double dt = parameters.sampleInterval_s;
    for (std::size_t i = 0; i < n; ++i) {
        ProbeOutput o;
        o.t_s = input.times.empty() ? input.t0_s + static_cast<double>(i) * dt : input.times[i];
        o.combined = results[0][0][i];
        for (std::size_t w = 0; w < workers; ++w) {
            for (std::size_t p = 0; p < results[w].size(); ++p) {
                const DetectorOutput& c = results[w][p][i];
                if (better(c.rab, p, c.lagAb, o.combined.rab, o.pairAb, o.combined.lagAb)) {
                    o.combined.rab = c.rab;
                    o.combined.lagAb = c.lagAb;
                    o.pairAb = p;
                }
                if (better(c.rba, p, c.lagBa, o.combined.rba, o.pairBa, o.combined.lagBa)) {
                    o.combined.rba = c.rba;
                    o.combined.lagBa = c.lagBa;
                    o.pairBa = p;
                }
            }
        }
        o.combined.decision = decide(o.combined.rab, o.combined.rba, resolved.threshold);
        outputs[i] = o;
    }
    return outputs;
}

std::vector<DefectEvent> segmentEvents(std::span<const ProbeOutput> outputs, double sampleInterval_s, double hold_s,
                                       std::optional<double> spacing_m)
{
    EventSegmenter segmenter(hold_s, spacing_m);
    std::vector<DefectEvent> events;
    for (const ProbeOutput& o : outputs) segmenter.push(o.t_s, o.combined, sampleInterval_s, events);
    segmenter.finish(events);
    return events;
}

}  // namespace tactiscope::core::detector
