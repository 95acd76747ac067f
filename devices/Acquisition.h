// Acquisition runs one device: a worker thread that pulls SampleBlocks from a
// BlockSource and hands each, in order, to every registered sink (live
// buffer, recorder, processors). It keeps counters the UI polls: samples,
// blocks, samples lost to sequence gaps, the measured rate, and the state.
//
// Threading: start(), stop(), addSink() and stats() are called from the
// owning (GUI) thread; sinks are called on the worker thread only.
#pragma once

#include "core/BlockSink.h"
#include "core/RateMeter.h"
#include "devices/BlockSource.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tactiscope::devices {

enum class AcquisitionState { Idle, Streaming, Finished, Failed };

struct AcquisitionStats {
    AcquisitionState state = AcquisitionState::Idle;
    std::uint64_t samples = 0;  // per channel, since start
    std::uint64_t blocks = 0;
    std::uint64_t samplesLost = 0;  // from gaps in the device's sample index
    std::optional<double> measuredRate_hz;
    std::optional<double> lastBlockHost_s;  // steady clock, when the newest block came
    std::string error;                      // set when state is Failed
};

class Acquisition {
public:
    // Throws std::invalid_argument for a null source.
    explicit Acquisition(std::unique_ptr<BlockSource> source);
    ~Acquisition();  // stops and joins the worker

    Acquisition(const Acquisition&) = delete;
    Acquisition& operator=(const Acquisition&) = delete;

    // Sinks must be added before start(). Throws std::logic_error otherwise.
    void addSink(std::shared_ptr<core::BlockSink> sink);

    void start();
    // Returns once the worker has finished its current read (at most one
    // read timeout) and exited. Safe to call when not running.
    void stop();

    AcquisitionStats stats() const;
    const BlockSource& source() const { return *m_source; }
    // For what a source takes from any thread (a shunt command, its answers).
    BlockSource& source() { return *m_source; }
    // The source's notices since the last call (any thread).
    std::vector<LinkNotice> takeNotices() { return m_source->takeNotices(); }
    // The channels the source grew to since the last call, after the sinks
    // were told (BlockSink::channelsGrew); none when it did not. Any thread.
    std::optional<std::vector<core::ChannelDescriptor>> takeGrownChannels()
    {
        const std::lock_guard lock(m_statsMutex);
        return std::exchange(m_grownChannels, std::nullopt);
    }

private:
    void run(const std::stop_token& stopToken);
    void fail(const std::string& message);

    std::unique_ptr<BlockSource> m_source;
    std::vector<std::shared_ptr<core::BlockSink>> m_sinks;
    mutable std::mutex m_statsMutex;
    AcquisitionStats m_stats;
    std::optional<std::vector<core::ChannelDescriptor>> m_grownChannels;  // not yet taken
    core::RateMeter m_rateMeter;
    std::jthread m_worker;
};

}  // namespace tactiscope::devices
