// Offline detection: lag subsets on worker threads, merged per sample.
#include "core/detector/OfflineDetection.h"

#include "core/detector/EventSegmenter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace tactiscope::core::detector {
namespace {

// Samples per chunk: the pair outputs of a chunk stay in cache, and memory
// does not grow with the recording beyond the result itself.
constexpr std::size_t kChunk = std::size_t{1} << 16;

// Larger R wins; on equal R the earlier pair, then the shorter lag, exactly
// as one ProbeDetector over all lags would choose.
bool better(double r, std::size_t pair, std::uint32_t lag, double bestR, std::size_t bestPair, std::uint32_t bestLag)
{
    if (r != bestR) return r > bestR;
    return pair != bestPair ? pair < bestPair : lag < bestLag;
}

// One worker: its lag subset for every pair, fed chunk by chunk.
struct Worker {
    std::vector<PairDetector> pairs;
    std::vector<std::vector<DetectorOutput>> outputs;  // per pair, one chunk

    void run(const SeriesInput& input, std::size_t first, std::size_t count)
    {
        for (std::size_t p = 0; p < pairs.size(); ++p) {
            outputs[p].resize(count);
            pairs[p].process(input.cantilevers[p].subspan(first, count), input.cantilevers[p + 1].subspan(first, count),
                             outputs[p]);
        }
    }
};

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> firstUnusableSample(const SeriesInput& input)
{
    for (std::size_t c = 0; c < input.cantilevers.size(); ++c)
        for (std::size_t i = 0; i < input.cantilevers[c].size(); ++i)
            if (!(std::abs(input.cantilevers[c][i]) <= kLargestUsableValue)) return std::pair(c, i);
    return std::nullopt;
}

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
    const std::size_t workerCount = std::max<std::size_t>(1, std::min<std::size_t>(threads, groups));
    std::vector<Worker> workers(workerCount);
    for (std::size_t w = 0; w < workerCount; ++w) {
        const std::size_t first = groups * w / workerCount * kLaneWidth;
        const std::size_t last = std::min(resolved.lags.size(), groups * (w + 1) / workerCount * kLaneWidth);
        DetectorParameters subset = parameters;
        subset.lags_s.clear();
        for (std::size_t i = first; i < last; ++i)
            subset.lags_s.push_back(static_cast<double>(resolved.lags[i]) * parameters.sampleInterval_s);
        for (std::size_t p = 0; p + 1 < input.cantilevers.size(); ++p) workers[w].pairs.emplace_back(subset);
        workers[w].outputs.resize(workers[w].pairs.size());
    }

    std::vector<ProbeOutput> outputs(n);
    const double dt = parameters.sampleInterval_s;
    for (std::size_t first = 0; first < n; first += kChunk) {
        const std::size_t count = std::min(kChunk, n - first);
        if (workerCount == 1) {
            workers[0].run(input, first, count);
        } else {
            std::vector<std::jthread> pool;
            for (auto& worker : workers) pool.emplace_back([&] { worker.run(input, first, count); });
        }
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t i = first + j;
            ProbeOutput o;
            o.t_s = input.times.empty() ? input.t0_s + static_cast<double>(i) * dt : input.times[i];
            o.combined = workers[0].outputs[0][j];
            for (const Worker& worker : workers) {
                for (std::size_t p = 0; p < worker.outputs.size(); ++p) {
                    const DetectorOutput& c = worker.outputs[p][j];
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

StretchDetection detectStretches(std::span<const std::vector<double>> cantilevers, const StretchSettings& settings)
{
    StretchDetection result;
    if (cantilevers.empty()) return result;
    const double dt_s = settings.parameters.sampleInterval_s;
    const std::size_t total = cantilevers.front().size();
    const auto complete = [&](std::size_t i) {
        return std::ranges::none_of(cantilevers, [i](const std::vector<double>& s) { return std::isnan(s[i]); });
    };
    for (std::size_t first = 0; first < total;) {
        if (!complete(first)) {
            ++first;
            continue;
        }
        std::size_t end = first;
        while (end < total && complete(end)) ++end;
        SeriesInput input{static_cast<double>(first) * dt_s, {}, {}};
        for (const auto& s : cantilevers) input.cantilevers.emplace_back(std::span(s).subspan(first, end - first));
        const auto outputs = detectSeries(input, settings.parameters, settings.threads);
        const auto found = segmentEvents(outputs, dt_s, settings.hold_s, settings.spacing_m);
        result.events.insert(result.events.end(), found.begin(), found.end());
        result.analysedSamples += end - first;
        first = end;
    }
    return result;
}

}  // namespace tactiscope::core::detector
