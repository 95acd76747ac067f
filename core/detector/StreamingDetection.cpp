// Streaming offline detection: halves of a run in time (or subsets of the
// lags) on worker threads, merged per sample into one reused run of
// outputs, events segmented as they come.
#include "core/detector/StreamingDetection.h"

#include <algorithm>
#include <atomic>
#include <barrier>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <thread>
#include <utility>

namespace tactiscope::core::detector {
namespace {

// Larger R wins; on equal R the earlier pair, then the shorter lag, exactly
// as one ProbeDetector over all lags would choose.
bool better(double r, std::size_t pair, std::uint32_t lag, double bestR, std::size_t bestPair, std::uint32_t bestLag)
{
    if (r != bestR) return r > bestR;
    return pair != bestPair ? pair < bestPair : lag < bestLag;
}

// Two states are the same to the bit (not merely ==: a −0 is not a +0).
bool sameBits(const std::vector<double>& x, const std::vector<double>& y)
{
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
}

bool sameMoments(const LagMoments& x, const LagMoments& y)
{
    for (std::size_t k = 0; k < x.mean.size(); ++k)
        if (!sameBits(x.mean[k], y.mean[k])) return false;
    for (std::size_t k = 0; k < x.moment.size(); ++k)
        if (!sameBits(x.moment[k], y.moment[k])) return false;
    return true;
}

// The samples after which the state no longer remembers where it started:
// 80 of the longest forgetting time plus the longest lag (the history then
// holds only real samples). e⁻⁴⁰ is below a double's resolution, but a
// moment can be 10⁴ times smaller at the junction than at the warm-up's
// start and a last ulp of difference lingers: on the simulated hour 40
// left most junctions one ulp apart, 50 none; 80 keeps a margin and costs
// under 5 % of a half run. 0 for the sliding window, which never forgets.
std::size_t warmUpOf(const ResolvedParameters& parameters)
{
    if (parameters.window != 0) return 0;
    double longest = 0.0;
    for (const double r : parameters.forgetting) longest = std::max(longest, 1.0 / (1.0 - r));
    return static_cast<std::size_t>(std::ceil(80.0 * longest)) + parameters.maxLag();
}

}  // namespace

// One worker: its lags for every pair (the workstation's detectors, or
// the probe's), each pair's outputs of one run.
struct StreamingDetection::Worker {
    std::vector<PairDetector> pairs;
    std::vector<FirmwarePairDetector> firmwarePairs;
    std::vector<std::vector<DetectorOutput>> outputs;

    // Samples [from, from + count) into the outputs from index `at` on.
    void run(std::span<const std::span<const double>> cantilevers, std::size_t from, std::size_t count,
             std::size_t at = 0)
    {
        for (std::size_t p = 0; p < pairs.size(); ++p)
            pairs[p].process(cantilevers[p].subspan(from, count), cantilevers[p + 1].subspan(from, count),
                             std::span(outputs[p]).subspan(at, count));
        for (std::size_t p = 0; p < firmwarePairs.size(); ++p)
            firmwarePairs[p].process(cantilevers[p].subspan(from, count), cantilevers[p + 1].subspan(from, count),
                                     std::span(outputs[p]).subspan(at, count));
    }
    void reset()
    {
        for (PairDetector& pair : pairs) pair.reset();
        for (FirmwarePairDetector& pair : firmwarePairs) pair.reset();
    }
};

struct StreamingDetection::Pool {
    std::barrier<> start;
    std::barrier<> done;
    std::atomic<bool> stopping{false};
    std::exception_ptr failure;  // a worker thread's, rethrown by the caller
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
      m_cantilevers(cantilevers),
      m_sink(std::move(sink)),
      m_segmenter(settings.hold_s, settings.spacing_m)
{
    if (cantilevers < 2) throw std::invalid_argument("a probe needs at least two cantilevers");
    const ResolvedParameters resolved = resolve(settings.parameters);
    m_threshold = resolved.threshold;
    m_lagCount = resolved.lags.size();
    m_warmUp = warmUpOf(resolved);
    if (!settings.filters.empty()) {
        const double rate_hz = 1.0 / settings.parameters.sampleInterval_s;
        if (settings.filters.size() != 1 && settings.filters.size() != cantilevers)
            throw std::invalid_argument("the detector takes one filter, or one per cantilever");
        for (std::size_t c = 0; c < cantilevers; ++c) {
            m_filters.emplace_back(settings.filters[settings.filters.size() == 1 ? 0 : c], rate_hz);
            if (c < settings.filterStartStates.size()) m_filters.back().startFrom(settings.filterStartStates[c]);
        }
        m_filtered.resize(cantilevers);
    }
    // A split in time pays while the warm-up is a small part of a half run.
    m_splitInTime = settings.engine == DetectorEngine::Workstation && settings.threads >= 2 && m_warmUp > 0 &&
                    m_warmUp <= kChunk / 16;

    std::size_t workerCount = 1;
    if (settings.engine == DetectorEngine::Probe) {
        m_runLength = kRun;
        m_workers.resize(1);
        for (std::size_t p = 0; p + 1 < cantilevers; ++p)
            m_workers.front().firmwarePairs.emplace_back(settings.parameters);
    } else if (m_splitInTime) {
        workerCount = 2;
        m_runLength = kChunk;
        m_workers.resize(2);
        for (Worker& worker : m_workers)
            for (std::size_t p = 0; p + 1 < cantilevers; ++p) worker.pairs.emplace_back(settings.parameters);
    } else {
        // Lag subsets of whole groups of 8, so every thread keeps its vectors full.
        const std::size_t groups = (resolved.lags.size() + kLaneWidth - 1) / kLaneWidth;
        workerCount = std::max<std::size_t>(1, std::min<std::size_t>(settings.threads, groups));
        m_runLength = kRun;
        m_workers.resize(workerCount);
        for (std::size_t w = 0; w < workerCount; ++w) {
            const std::size_t first = groups * w / workerCount * kLaneWidth;
            const std::size_t last = std::min(resolved.lags.size(), groups * (w + 1) / workerCount * kLaneWidth);
            DetectorParameters subset = settings.parameters;
            subset.lags_s.clear();
            for (std::size_t i = first; i < last; ++i)
                subset.lags_s.push_back(static_cast<double>(resolved.lags[i]) * settings.parameters.sampleInterval_s);
            for (std::size_t p = 0; p + 1 < cantilevers; ++p) m_workers[w].pairs.emplace_back(subset);
        }
    }
    for (Worker& worker : m_workers) worker.outputs.assign(cantilevers - 1, std::vector<DetectorOutput>(m_runLength));
    m_outputs.resize(m_runLength);
    if (workerCount > 1) {
        m_pool = std::make_unique<Pool>(workerCount);
        for (std::size_t w = 1; w < workerCount; ++w) {
            m_pool->threads.emplace_back([this, w] {
                while (true) {
                    m_pool->start.arrive_and_wait();
                    if (m_pool->stopping) return;
                    try {
                        m_job(w);
                    } catch (...) {
                        m_pool->failure = std::current_exception();
                    }
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

void StreamingDetection::runWorkers(const std::function<void(std::size_t)>& job)
{
    m_job = job;
    if (m_pool) m_pool->start.arrive_and_wait();
    try {
        job(0);
    } catch (...) {
        // The others still meet at the barrier, or they and the destructor
        // would wait for each other for ever.
        if (m_pool) m_pool->done.arrive_and_wait();
        throw;
    }
    if (!m_pool) return;
    m_pool->done.arrive_and_wait();
    if (m_pool->failure) std::rethrow_exception(std::exchange(m_pool->failure, nullptr));
}

void StreamingDetection::push(std::span<const std::span<const double>> cantilevers, std::span<const double> times)
{
    if (cantilevers.size() != m_cantilevers) throw std::invalid_argument("a push needs every cantilever");
    const std::size_t n = cantilevers.front().size();
    for (const auto& series : cantilevers)
        if (series.size() != n) throw std::invalid_argument("cantilever series differ in length");
    if (!times.empty() && times.size() != n)
        throw std::invalid_argument("times and cantilever series differ in length");
    if (m_filters.empty()) return pushSamples(cantilevers, times);
    std::vector<std::span<const double>> filtered;
    for (std::size_t c = 0; c < m_cantilevers; ++c) {
        m_filtered[c].assign(cantilevers[c].begin(), cantilevers[c].end());
        m_filters[c].process(m_filtered[c]);
        filtered.emplace_back(m_filtered[c]);
    }
    pushSamples(filtered, times);
}

void StreamingDetection::pushSamples(std::span<const std::span<const double>> cantilevers,
                                     std::span<const double> times)
{
    const std::size_t n = cantilevers.front().size();
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
        while (to < n && to - from < m_runLength && complete(to)) ++to;
        if (!m_stretchStart) m_stretchStart = m_next + from;
        runStretch(cantilevers, times, from, to - from);
        from = to;
    }
    m_next += n;
}

std::size_t StreamingDetection::runSplitInTime(std::span<const std::span<const double>> cantilevers, std::size_t from,
                                               std::size_t count)
{
    const std::size_t half = count / 2;
    Worker& lead = m_workers[m_lead];
    Worker& next = m_workers[1 - m_lead];
    std::vector<PairDetector::Snapshot> junction(next.pairs.size());
    runWorkers([&](std::size_t w) {
        if (w == 0) {
            lead.run(cantilevers, from, half);
            return;
        }
        // From silence, over the warm-up (its outputs are overwritten), to
        // the junction; its state there is kept to check.
        for (PairDetector& pair : next.pairs) pair.reset();
        next.run(cantilevers, from + half - m_warmUp, m_warmUp, half);
        for (std::size_t p = 0; p < next.pairs.size(); ++p) junction[p] = next.pairs[p].snapshot();
        next.run(cantilevers, from + half, count - half, half);
    });
    ++m_timeSplits.junctions;
    bool exact = true;
    for (std::size_t p = 0; p < lead.pairs.size(); ++p)
        exact = exact && sameMoments(lead.pairs[p].snapshot().moments, junction[p].moments);
    if (exact) {
        m_lead = 1 - m_lead;  // it holds the true state now
        return m_lead;
    }
    ++m_timeSplits.recomputed;
    lead.run(cantilevers, from + half, count - half, half);
    return m_lead;
}

// The run [from, from + count) of this push, inside one stretch: the
// workers' share of it, then the best of every pair (and worker) per sample.
void StreamingDetection::runStretch(std::span<const std::span<const double>> cantilevers, std::span<const double> times,
                                    std::size_t from, std::size_t count)
{
    const double dt = m_settings.parameters.sampleInterval_s;
    const double stretchT0_s = m_t0_s + static_cast<double>(*m_stretchStart) * dt;
    const std::uint64_t first = m_next + from;
    // Which workers' buffers hold sample j: all of them (a lag split), or
    // one per half (a split in time).
    std::span<const Worker> firstHalf = m_workers, secondHalf = m_workers;
    std::size_t half = count;
    if (m_splitInTime) {
        const std::size_t firstWorker = m_lead;
        if (count >= 4 * m_warmUp) {
            half = count / 2;
            const std::size_t secondWorker = runSplitInTime(cantilevers, from, count);
            secondHalf = std::span(m_workers).subspan(secondWorker, 1);
        } else {
            m_workers[m_lead].run(cantilevers, from, count);  // too short to split
        }
        firstHalf = std::span(m_workers).subspan(firstWorker, 1);
    } else {
        runWorkers([&](std::size_t w) { m_workers[w].run(cantilevers, from, count); });
    }
    for (std::size_t j = 0; j < count; ++j) {
        ProbeOutput& o = m_outputs[j];
        o.t_s = times.empty() ? stretchT0_s + static_cast<double>(first + j - *m_stretchStart) * dt : times[from + j];
        const std::span<const Worker> sources = j < half ? firstHalf : secondHalf;
        o.combined = sources.front().outputs.front()[j];
        o.pairAb = 0;
        o.pairBa = 0;
        for (const Worker& worker : sources) {
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
    for (Worker& worker : m_workers) worker.reset();
    m_lead = 0;
    m_stretchStart.reset();
}

StretchDetection StreamingDetection::finish()
{
    m_segmenter.finish(m_result.events);
    return std::move(m_result);
}

}  // namespace tactiscope::core::detector
