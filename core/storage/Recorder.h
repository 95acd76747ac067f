// Records one session into a store: a BlockSink whose consume() only
// queues, so the acquisition thread never waits on the disk, and a writer
// thread with its own connection that stores whatever is queued in one
// transaction at least every kCommitInterval.
//
// Memory is bounded: beyond maxQueuedSamples (per channel) blocks are
// dropped and the store records them as a gap, as if the device had lost
// them (at the end of the recording too); stats() counts them. A write error (disk full, file made read-only)
// stops the recording: everything committed stays, stats() says why.
//
// Sample indices and times are stored relative to the first block, so a
// session starts at sample 0, time 0.
#pragma once

#include "core/BlockSink.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/SessionStore.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace tactiscope::core::storage {

struct RecorderStats {
    std::uint64_t samplesWritten = 0;  // per channel, committed
    std::uint64_t samplesDropped = 0;  // per channel, over the memory bound or after a failure
    // Per channel, committed: values that were no number (NaN, a text
    // board's "nan"), holes in that channel alone.
    std::vector<std::uint64_t> holes;
    std::uint64_t eventsWritten = 0;
    std::uint64_t readingsWritten = 0;
    std::uint64_t commits = 0;
    std::string error;  // why recording stopped early; empty while it is fine
};

class Recorder final : public BlockSink {
public:
    static constexpr std::chrono::milliseconds kCommitInterval{250};

    // Takes the store's RecorderLock (one recorder per store), refuses a
    // damaged store, marks sessions a crash left "recording" as
    // interrupted, and begins the session (a device's part of a session of
    // several, metadata.partOf, does neither of the first and last: the
    // recording of the whole session holds the lock, SessionOfDevices),
    // linked with the stored calibrations it uses. Throws StorageError, e.g.
    // when another recorder holds the store.
    Recorder(const std::string& storePath, const SessionMetadata& metadata, std::vector<ChannelDescriptor> channels,
             double sampleRate_hz, std::uint64_t maxQueuedSamples, const std::vector<std::int64_t>& calibrations = {});
    ~Recorder() override;  // finish(Interrupted) unless finished

    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    std::int64_t sessionId() const { return m_session; }
    void consume(const SampleBlock& block) override;  // acquisition thread
    // Told the device's index of the recording's first sample when its
    // block comes (a signal chain restarts its filters there, so the live
    // filtered series is what re-analysis computes from the stored
    // samples); on the thread that passes the block. Set before the first.
    void watchFirstSample(std::function<void(std::uint64_t)> watch) { m_firstSampleWatch = std::move(watch); }
    // The device's channels, grown while recording (a board printing lines
    // began to print another value): those past the session's are added to
    // it with the next commit, holes before (SessionStore::addChannels).
    // Blocks of them may follow at once. Any thread.
    void addChannels(const std::vector<ChannelDescriptor>& all);
    // Events (e.g. an operator's marker) stored with the next commit; any thread.
    void addEvents(std::vector<SessionEvent> events);
    // Readings (e.g. a press's stiffness), likewise; times on the session clock.
    void addReadings(std::vector<SessionReading> readings);
    // A zero the processor reads samples on from stream sample `streamIndex`
    // (the device's index, before the session's rebase); one from before
    // the first recorded sample applies from the session's start. Any thread.
    void addZero(std::uint64_t streamIndex, std::string valuesJson);
    // Samples that should have come after the last one consumed, to a
    // session time (a probe that went and did not come back): finish()
    // records them as a gap at the session's end. Any thread.
    void markLostUntil(double sessionTime_s);
    // The mapping of a part's clock onto its session's (ClockMappingJson),
    // stored with the next commit; any thread.
    void setClockMapping(std::string clockJson);
    // The session's signal setup again, now with where its filters stood
    // at its first sample (core/signal/SignalSetup.h), stored with the next
    // commit; any thread.
    void setSignalSetup(std::string setupJson);
    // The session time of the newest sample consumed (0 before the first).
    double sessionTime_s() const;
    // The acquisition time (a block's clock) of the newest sample consumed;
    // none before the first.
    std::optional<double> consumedUntil_s() const;
    // An acquisition time (a block's clock) on the session's clock.
    double sessionTimeOf(double acquisitionTime_s) const;
    // The acquisition time of the session's t = 0: its first sample's; none
    // before the first block.
    std::optional<double> acquisitionOrigin_s() const;
    RecorderStats stats() const;
    // Stores what is queued, ends the session with `status` (interrupted if
    // a write failed) and its automatic verdict, if any, or why its mode
    // gave none (`unjudged`), and stops the writer. Idempotent.
    RecorderStats finish(SessionStatus status, const std::optional<VerdictDecision>& verdict = std::nullopt,
                         const std::string& unjudged = {});

private:
    std::chrono::system_clock::time_point endOnTheWallClock();
    void run(const std::stop_token& stop);
    void writeQueued(std::unique_lock<std::mutex>& lock);

    double m_sampleRate_hz;
    // Held before the store is touched, released last; none for a device's
    // part of a session of several, whose recording holds it for all parts.
    std::optional<RecorderLock> m_lock;
    SessionStore m_store;
    std::int64_t m_session = 0;
    std::uint64_t m_maxQueued;
    mutable std::mutex m_mutex;
    std::size_t m_channelCount;                       // the session's, with those queued
    std::vector<ChannelDescriptor> m_queuedChannels;  // gained, not yet stored
    std::condition_variable_any m_wake;
    std::deque<SampleBlock> m_queue;
    std::vector<SessionEvent> m_queuedEvents;
    std::vector<SessionReading> m_queuedReadings;
    std::vector<SessionZero> m_queuedZeros;  // stream indices until the first block is seen
    std::optional<std::string> m_queuedClock;
    std::optional<std::string> m_queuedSignal;
    std::uint64_t m_queuedSamples = 0;
    std::optional<std::uint64_t> m_firstIndex;  // of the first block consumed
    std::function<void(std::uint64_t)> m_firstSampleWatch;
    double m_firstTime_s = 0.0;
    std::optional<double> m_consumedUntil_s;  // acquisition time of the newest sample consumed
    std::uint64_t m_consumedEnd = 0;          // one past the last sample consumed, session-relative
    RecorderStats m_stats;
    bool m_finished = false;
    // Cut by a trigger: its first samples were taken before the recorder
    // was made (its pre-trigger time), so its start is dated back from its
    // end by its length when it finishes.
    bool m_triggered = false;
    // The session's start on the host's wall clock (its stored start) and
    // on the steady clock: the end is dated by how long it lasted when the
    // wall clock was set while recording.
    std::chrono::system_clock::time_point m_wallStart;
    std::chrono::steady_clock::time_point m_steadyStart;
    std::jthread m_writer;  // last: stopped before the members it uses go
};

}  // namespace tactiscope::core::storage
