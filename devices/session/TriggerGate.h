// The triggered recording's gate on the acquisition thread: it runs the
// trigger's rules (core/trigger/TriggerMachine) on every sample of the
// watched quantity, holds the last pre-trigger seconds of blocks, and
// passes each triggered session's samples, exactly [first, end) of the
// stream, to the recorder the owner attaches for it. The owner (the live
// session) sees a session's start in pendingStart(), makes its recorder and
// attach()es it (the held blocks from its first sample go in at once), and
// finishes it once takeFinished() hands the recorder back after its last
// sample. Memory is bounded: blocks held longer than the backlog bound (an
// owner that does not attach) are dropped, and the recording shows a gap.
//
// Threading: consume() on the acquisition thread; the rest from the owner.
#pragma once

#include "core/BlockSink.h"
#include "core/storage/Recorder.h"
#include "core/trigger/TriggerMachine.h"
#include "devices/session/LiveQuantity.h"

#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace tactiscope::devices::session {

// A triggered session as the gate cut it: its span of stream samples and
// the stream time of its trigger instant.
struct TriggeredSession {
    core::trigger::TriggeredSpan span;  // end: 0 while still open
    double triggerTime_s = 0.0;
};

// A session the trigger started: its number since the arming (1 for the
// first) and the stream time of its trigger instant.
struct TriggeredStart {
    unsigned session = 0;
    double trigger_s = 0.0;
};

struct TriggerStatus {
    core::trigger::TriggerState state = core::trigger::TriggerState::Waiting;
    unsigned sessionsCut = 0;
    bool valueSeen = false;  // TriggerMachine::valueSeen
};

class TriggerGate final : public core::BlockSink {
public:
    // Arms the trigger (replacing one armed before; a session it had open
    // is dropped: the owner finishes its recording first). Throws
    // std::invalid_argument for settings the machine refuses.
    void arm(const core::trigger::TriggerSettings& settings, QuantityReader reader, double sampleRate_hz,
             double maxBacklog_s);
    void disarm();
    bool armed() const;
    // The watched quantity from another processor (one rebuilt), the
    // trigger's state kept.
    void replaceReader(QuantityReader reader);
    TriggerStatus status() const;

    // A session triggered and waiting for its recorder.
    std::optional<TriggeredSession> pendingStart() const;
    // Sessions cut that have no recorder yet.
    std::size_t waiting() const;
    // The stream time of the earliest sample a session not yet recording
    // may start at (one triggered and waiting, or one triggered by the
    // samples to come, reaching back its pre-trigger time): results that
    // end after it may belong to a recording and wait. None when disarmed.
    std::optional<double> reachBack_s() const;
    // Its recorder: from now on it gets the session's samples, the held
    // ones first.
    void attach(std::shared_ptr<core::storage::Recorder> recorder);
    // A session all of whose samples went to its recorder: the recorder is
    // detached and handed back with the session, for the owner to finish.
    struct Finished {
        TriggeredSession session;
        std::shared_ptr<core::storage::Recorder> recorder;
    };
    std::optional<Finished> takeFinished();
    // The recorder attached, taken off (a stop while a session is open):
    // no further sample reaches it.
    std::shared_ptr<core::storage::Recorder> detach();

    void consume(const core::SampleBlock& block) override;
    // To the recorder attached, and to each attached later.
    void channelsGrew(const std::vector<core::ChannelDescriptor>& all) override;

private:
    void forward();  // with m_mutex held
    void trim();     // with m_mutex held

    mutable std::mutex m_mutex;
    std::optional<core::trigger::TriggerMachine> m_machine;
    QuantityReader m_reader;
    std::vector<double> m_values;
    std::uint64_t m_maxBacklog = 0;  // samples
    double m_rate_hz = 1.0;
    std::deque<core::SampleBlock> m_held;
    std::deque<TriggeredSession> m_sessions;  // the front one is the recorder's, once attached
    std::shared_ptr<core::storage::Recorder> m_recorder;
    std::uint64_t m_forwardedUntil = 0;  // the front session's samples before this went to its recorder
    std::optional<Finished> m_finished;
    std::vector<core::ChannelDescriptor> m_grownTo;  // the device's channels, once they grew
};

}  // namespace tactiscope::devices::session
