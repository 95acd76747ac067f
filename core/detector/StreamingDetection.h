// Offline detection as a stream, for the CLI's detect and analyze, the
// review's re-analysis and the derived detector channels: samples go in a
// chunk at a time (from a CSV reader or the store), events come out, and
// per-sample outputs go to a sink only when someone asked for them. Every
// buffer is allocated once, so memory does not grow with the recording.
//
// Threads give the same outputs as one, bit for bit. With the exponential
// form and two or more threads each run is split in time: the first half
// continues the true state, the second starts a warm-up before its first
// sample (80 forgetting times plus the longest lag) on another core; where
// the warmed-up state is not the true one to the bit at the junction, the
// second half is recomputed from the true state. Otherwise (the sliding window, whose
// running sums never forget; a forgetting time too long to warm up) the
// threads split the lag set, which is exact as every lag is independent
// but pays less: each worker also carries the per-sample work that does
// not depend on the lag count (docs/performance.md).
//
// A sample where some cantilever has no value (NaN: lost on the way) ends a
// stretch: the detector restarts after it, as a reconnection restarts the
// live detector, and the open event is closed.
#pragma once

#include "core/detector/DefectEvent.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/EventSegmenter.h"
#include "core/detector/FirmwarePairDetector.h"
#include "core/detector/PairDetector.h"
#include "core/detector/ProbeDecisionCheck.h"
#include "core/detector/ProbeDetector.h"
#include "core/dsp/ChannelFilter.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::core::detector {

// Which detector runs: the workstation's (double precision, vectorised,
// on threads) or the probe's own (firmware/probe-detector: single
// precision, exponential form, one thread), to compare what a probe
// decides with what the workstation decides on the same samples.
enum class DetectorEngine { Workstation, Probe };

// How a recording is re-analysed (the CLI's analyze, the review view).
struct StretchSettings {
    DetectorParameters parameters;  // sampleInterval_s is the series'
    double hold_s = 0.020;
    std::optional<double> spacing_m;
    unsigned threads = 1;  // the workstation's engine only
    DetectorEngine engine = DetectorEngine::Workstation;
    // The filters the cantilevers go through first (a mains notch under
    // hum: docs/detector.md), causal as live: one for every cantilever, or
    // one each (an empty one leaves its cantilever as it is); none: the
    // samples as they are.
    std::vector<dsp::FilterSettings> filters = {};
    // Where each cantilever's filter stood at the first sample pushed (a
    // recording's, core/signal/SignalSetup.h); none: afresh.
    std::vector<std::optional<std::vector<double>>> filterStartStates = {};
};

struct StretchDetection {
    std::vector<DefectEvent> events;  // in time order
    std::size_t analysedSamples = 0;  // samples where every cantilever had a value
    // A stored probe's own decisions against these (core/derived/StoredDetection).
    std::optional<ProbeAgreement> probeAgreement;
};

class StreamingDetection {
public:
    // A good number of samples per push (a store window, a CSV block:
    // 2 MB a channel); pushes of any length are taken.
    static constexpr std::size_t kChunk = std::size_t{1} << 18;
    // Samples the workers take per run when they split the lags: their
    // outputs stay in cache until merged. (A split in time takes kChunk:
    // the longer the halves, the less the warm-up costs.)
    static constexpr std::size_t kRun = std::size_t{1} << 14;

    // Per-sample outputs of a run of samples without a gap, with the
    // recording index of the first; valid during the call only.
    using SampleSink = std::function<void(std::uint64_t firstIndex, std::span<const ProbeOutput> outputs)>;

    // Throws std::invalid_argument for fewer than two cantilevers or bad
    // parameters. Times are t0_s + index·Δt unless push() is given them.
    StreamingDetection(std::size_t cantilevers, const StretchSettings& settings, double t0_s = 0.0,
                       SampleSink sink = {});
    ~StreamingDetection();
    StreamingDetection(const StreamingDetection&) = delete;
    StreamingDetection& operator=(const StreamingDetection&) = delete;

    // The next samples of every cantilever (equal lengths, probe order) and,
    // optionally, each one's own time (a file's t column).
    void push(std::span<const std::span<const double>> cantilevers, std::span<const double> times = {});
    // Ends the stream: the open event is reported. The object is spent.
    StretchDetection finish();

    std::uint64_t samplesPushed() const { return m_next; }
    std::size_t lagCount() const { return m_lagCount; }

    // How often a run was split in time, and how often the second half's
    // warm-up did not reach the true state to the bit and was recomputed.
    struct TimeSplits {
        std::size_t junctions = 0;
        std::size_t recomputed = 0;
    };
    TimeSplits timeSplits() const { return m_timeSplits; }

private:
    struct Worker;
    // Worker threads live as long as the detection: each run starts them
    // through one barrier and waits for them at another (a thread per run
    // cost more than the work of a short run).
    struct Pool;

    void pushSamples(std::span<const std::span<const double>> cantilevers, std::span<const double> times);
    void runStretch(std::span<const std::span<const double>> cantilevers, std::span<const double> times,
                    std::size_t from, std::size_t count);
    // Runs job(w) for every worker w, w = 0 on the calling thread.
    void runWorkers(const std::function<void(std::size_t)>& job);
    // The lead's first half and the other worker's warmed-up second half;
    // returns the worker whose buffers hold samples [half, count).
    std::size_t runSplitInTime(std::span<const std::span<const double>> cantilevers, std::size_t from,
                               std::size_t count);
    void restart();

    StretchSettings m_settings;
    std::vector<dsp::ChannelFilter> m_filters;    // per cantilever, when filtered
    std::vector<std::vector<double>> m_filtered;  // their outputs, reused
    double m_t0_s;
    double m_threshold = 0.0;
    std::size_t m_lagCount = 0;
    std::size_t m_cantilevers = 0;
    SampleSink m_sink;
    std::vector<Worker> m_workers;
    std::unique_ptr<Pool> m_pool;            // none with one worker
    std::function<void(std::size_t)> m_job;  // what the pool runs
    // Split in time (two workers with every lag) rather than by lags: the
    // samples a warm-up takes, and which worker holds the true state.
    bool m_splitInTime = false;
    std::size_t m_warmUp = 0;
    std::size_t m_lead = 0;
    TimeSplits m_timeSplits;
    std::size_t m_runLength = 0;         // samples per run at most
    std::vector<ProbeOutput> m_outputs;  // one run, reused
    EventSegmenter m_segmenter;
    StretchDetection m_result;
    std::uint64_t m_next = 0;                     // recording index of the next sample
    std::optional<std::uint64_t> m_stretchStart;  // index where the current stretch began
};

}  // namespace tactiscope::core::detector
