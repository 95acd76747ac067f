// Offline detection as a stream, for the CLI's detect and analyze, the
// review's re-analysis and the derived detector channels: samples go in a
// chunk at a time (from a CSV reader or the store), events come out, and
// per-sample outputs go to a sink only when someone asked for them. Every
// buffer is allocated once, so memory does not grow with the recording.
//
// Threads split the lag set, which is exact: every lag's statistics are
// independent of the others, so any thread count gives the same outputs,
// bit for bit. It pays less than the cores: each worker also carries the
// per-sample work that does not depend on the lag count (measured in
// docs/performance.md). A split in time would scale further but is exact
// only where a warm-up's state matches the true one to the bit, which the
// exponential state approaches without a bound that holds for every input.
//
// A sample where some cantilever has no value (NaN: lost on the way) ends a
// stretch: the detector restarts after it, as a reconnection restarts the
// live detector, and the open event is closed.
#pragma once

#include "core/detector/DefectEvent.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/EventSegmenter.h"
#include "core/detector/PairDetector.h"
#include "core/detector/ProbeDetector.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::core::detector {

// How a recording is re-analysed (the CLI's analyze, the review view).
struct StretchSettings {
    DetectorParameters parameters;  // sampleInterval_s is the series'
    double hold_s = 0.020;
    std::optional<double> spacing_m;
    unsigned threads = 1;
};

struct StretchDetection {
    std::vector<DefectEvent> events;  // in time order
    std::size_t analysedSamples = 0;  // samples where every cantilever had a value
};

class StreamingDetection {
public:
    // A good number of samples per push (a store window, a CSV block);
    // pushes of any length are taken.
    static constexpr std::size_t kChunk = std::size_t{1} << 16;
    // Samples the workers take per run: their outputs stay in cache until
    // merged.
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

private:
    struct Worker;
    void runStretch(std::span<const std::span<const double>> cantilevers, std::span<const double> times,
                    std::size_t from, std::size_t count);
    void restart();
    void runWorkers(std::size_t from, std::size_t count);

    // Worker threads live as long as the detection: each run starts them
    // through one barrier and waits for them at another (a thread per run
    // cost more than the work of a short run).
    struct Pool;

    StretchSettings m_settings;
    double m_t0_s;
    double m_threshold = 0.0;
    std::size_t m_lagCount = 0;
    SampleSink m_sink;
    std::vector<Worker> m_workers;
    std::unique_ptr<Pool> m_pool;                         // none with one worker
    std::span<const std::span<const double>> m_runInput;  // what the pool's run reads
    std::size_t m_runFrom = 0;
    std::size_t m_runCount = 0;
    std::vector<ProbeOutput> m_outputs;  // one chunk, reused
    EventSegmenter m_segmenter;
    StretchDetection m_result;
    std::uint64_t m_next = 0;                       // recording index of the next sample
    std::optional<std::uint64_t> m_stretchStart;    // index where the current stretch began
    std::vector<std::span<const double>> m_slices;  // per cantilever, reused
};

// Events whose lags were put in seconds with `usedInterval_s` restated with
// the recording's exact mean interval (a file read as a stream knows it
// only at its end): the same lags in samples, their seconds and the speeds
// from `interval_s`, as if that had been used from the start.
void restateLags(std::span<DefectEvent> events, double usedInterval_s, double interval_s,
                 std::optional<double> spacing_m);

}  // namespace tactiscope::core::detector
