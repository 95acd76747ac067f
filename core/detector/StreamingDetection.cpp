// Streaming offline detection: lag subsets on worker threads, merged per
// sample into one reused chunk of outputs, events segmented as they come.
#include "core/detector/StreamingDetection.h"

#include <algorithm>
#include <atomic>
#include <barrier>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace tactiscope::core::detector {
namespace {

// Larger R wins; on equal R the earlier pair, then the shorter lag, exactly
// as one ProbeDetector over all lags would choose.
bool better(double r, std::size_t pair, std::uint32_t lag, double bestR, std::size_t bestPair, std::uint32_t bestLag)
{
    if (r != bestR) return r > bestR;
    return pair != bestPair ? pair < bestPair : lag < bestLag;
}

}  // namespace

// One worker: its lag subset for every pair, each pair's outputs of one chunk.
struct StreamingDetection::Worker {
    std::vector<PairDetector> pairs;
    std::vector<std::vector<DetectorOutput>> outputs;

    void run(std::span<const std::span<const double>> cantilevers, std::size_t from, std::size_t count)
    {
        for (std::size_t p = 0; p < pairs.size(); ++p)
            pairs[p].process(cantilevers[p].subspan(from, count), cantilevers[p + 1].subspan(from, count),
                             std::span(outputs[p]).first(count));
    }
};

struct StreamingDetection::Pool {
    std::barrier<> start;
    std::barrier<> done;
    std::atomic<bool> stopping{false};
    std::vector<std::jthread> threads;

    explicit Pool(std::size_t workers)
        : start(static_cast<std::ptrdiff_t>(workers)),
          done(static_cast<std::ptrdiff_t>(workers))
    {
    }
};

StreamingDetection::StreamingDetection(std::size_t cantilevers, const StretchSettings& settings, double t0_s,
                                       SampleSink sink)
    : m_settings(settings),
      m_t0_s(t0_s),
      m_sink(std::move(sink)),
      m_segmenter(settings.hold_s, settings.spacing_m)
{
    if (cantilevers < 2) throw std::invalid_argument("a probe needs at least two cantilevers");
    const ResolvedParameters resolved = resolve(settings.parameters);
    m_threshold = resolved.threshold;
    m_lagCount = resolved.lags.size();

    // Lag subsets of whole groups of 8, so every thread keeps its vectors full.
    const std::size_t groups = (resolved.lags.size() + kLaneWidth - 1) / kLaneWidth;
    const std::size_t workerCount = std::max<std::size_t>(1, std::min<std::size_t>(settings.threads, groups));
    m_workers.resize(workerCount);
    for (std::size_t w = 0; w < workerCount; ++w) {
        const std::size_t first = groups * w / workerCount * kLaneWidth;
        const std::size_t last = std::min(resolved.lags.size(), groups * (w + 1) / workerCount * kLaneWidth);
        DetectorParameters subset = settings.parameters;
        subset.lags_s.clear();
        for (std::size_t i = first; i < last; ++i)
            subset.lags_s.push_back(static_cast<double>(resolved.lags[i]) * settings.parameters.sampleInterval_s);
        for (std::size_t p = 0; p + 1 < cantilevers; ++p) m_workers[w].pairs.emplace_back(subset);
        m_workers[w].outputs.assign(cantilevers - 1, std::vector<DetectorOutput>(kRun));
    }
    m_outputs.resize(kRun);
    m_slices.resize(cantilevers);
    if (workerCount > 1) {
        m_pool = std::make_unique<Pool>(workerCount);
        for (std::size_t w = 1; w < workerCount; ++w) {
            m_pool->threads.emplace_back([this, w] {
                while (true) {
                    m_pool->start.arrive_and_wait();
                    if (m_pool->stopping) return;
                    m_workers[w].run(m_runInput, m_runFrom, m_runCount);
                    m_pool->done.arrive_and_wait();
                }
            });
        }
    }
}

StreamingDetection::~StreamingDetection()
{
    if (!m_pool) return;
    m_pool->stopping = true;
    m_pool->start.arrive_and_wait();  // the threads see `stopping` and end
    m_pool->threads.clear();          // joined
}

// Every worker's lags over [from, from + count) of m_runInput; the calling
// thread is worker 0.
void StreamingDetection::runWorkers(std::size_t from, std::size_t count)
{
    m_runFrom = from;
    m_runCount = count;
    if (m_pool) m_pool->start.arrive_and_wait();
    m_workers.front().run(m_runInput, from, count);
    if (m_pool) m_pool->done.arrive_and_wait();
}

void StreamingDetection::push(std::span<const std::span<const double>> cantilevers, std::span<const double> times)
{
    if (cantilevers.size() != m_slices.size()) throw std::invalid_argument("a push needs every cantilever");
    const std::size_t n = cantilevers.front().size();
    for (const auto& series : cantilevers)
        if (series.size() != n) throw std::invalid_argument("cantilever series differ in length");
    if (!times.empty() && times.size() != n)
        throw std::invalid_argument("times and cantilever series differ in length");
    const auto complete = [&](std::size_t i) {
        return std::ranges::none_of(cantilevers, [i](std::span<const double> s) { return std::isnan(s[i]); });
    };
    for (std::size_t from = 0; from < n;) {
        if (!complete(from)) {
            if (m_stretchStart) restart();
            ++from;
            continue;
        }
        std::size_t to = from;
        while (to < n && to - from < kRun && complete(to)) ++to;
        if (!m_stretchStart) m_stretchStart = m_next + from;
        runStretch(cantilevers, times, from, to - from);
        from = to;
    }
    m_next += n;
}

// The run [from, from + count) of this push, inside one stretch: every
// worker's lags, then the merge of their bests per sample.
void StreamingDetection::runStretch(std::span<const std::span<const double>> cantilevers, std::span<const double> times,
                                    std::size_t from, std::size_t count)
{
    const double dt = m_settings.parameters.sampleInterval_s;
    const double stretchT0_s = m_t0_s + static_cast<double>(*m_stretchStart) * dt;
    const std::uint64_t first = m_next + from;
    m_runInput = cantilevers;
    runWorkers(from, count);
    for (std::size_t j = 0; j < count; ++j) {
        ProbeOutput& o = m_outputs[j];
        o.t_s = times.empty() ? stretchT0_s + static_cast<double>(first + j - *m_stretchStart) * dt : times[from + j];
        o.combined = m_workers.front().outputs.front()[j];
        o.pairAb = 0;
        o.pairBa = 0;
        for (const Worker& worker : m_workers) {
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
        o.combined.decision = decide(o.combined.rab, o.combined.rba, m_threshold);
        m_segmenter.push(o.t_s, o.combined, dt, m_result.events);
    }
    if (m_sink) m_sink(first, std::span<const ProbeOutput>(m_outputs).first(count));
    m_result.analysedSamples += count;
}

// A gap: the open event ends, and the detector starts again from silence.
void StreamingDetection::restart()
{
    m_segmenter.finish(m_result.events);
    m_segmenter.reset();
    for (Worker& worker : m_workers)
        for (PairDetector& pair : worker.pairs) pair.reset();
    m_stretchStart.reset();
}

StretchDetection StreamingDetection::finish()
{
    m_segmenter.finish(m_result.events);
    return std::move(m_result);
}

void restateLags(std::span<DefectEvent> events, double usedInterval_s, double interval_s,
                 std::optional<double> spacing_m)
{
    if (usedInterval_s == interval_s) return;
    for (DefectEvent& e : events) {
        const double samples = std::round(e.peakLag_s / usedInterval_s);
        e.peakLag_s = samples * interval_s;
        e.speed_m_per_s.reset();
        if (spacing_m && e.peakLag_s > 0.0) e.speed_m_per_s = *spacing_m / e.peakLag_s;
    }
}

}  // namespace tactiscope::core::detector
