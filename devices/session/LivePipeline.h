// The one live pipeline (issue 52): a session of N devices, one device
// being N = 1, run the same way whoever runs it: `tactiscope-cli record`
// with one or several --port, the GUI's live station, a triggered run. It
// owns each device's LiveSession (acquisition, mode units, limits, trigger
// gate) and records them into one session: a session of one device, or
// one of several whose parts SessionOfDevices begins, maps onto its clock
// and ends with its parts' verdict. The rules of a session's end live
// here and in the LiveSessions, never in an owner: a device whose link
// failed or whose stream finished ends its recording (its part only, in a
// session of several), a session of several ends once its last part has.
// The owner calls poll() and reads one value, PipelineNews: everything that
// happened since the last poll.
//
// Threading: every call from one owner thread (the GUI thread, the CLI's
// main loop), as LiveSession's.
#pragma once

#include "core/Vocabulary.h"
#include "core/storage/SessionSource.h"
#include "core/trigger/TriggerMachine.h"
#include "devices/BlockSource.h"
#include "devices/LinkNotice.h"
#include "devices/session/LimitAlarms.h"
#include "devices/session/LiveRecords.h"
#include "devices/session/LiveSession.h"
#include "devices/session/TriggerGate.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::session {

class SessionOfDevices;

// What one device said or did, with its name in the session (empty for
// the only device of a session of one).
template <typename What>
struct FromDevice {
    std::string device;
    What what;
};

// A recording that ended, whichever way: stopped, by the disk, by the
// link, or cut by the trigger.
struct RecordingEnd {
    std::int64_t session = 0;  // the session (of several devices: the whole one)
    std::string subject;       // what it inspected (a triggered one's numbered: door-18)
    bool triggered = false;    // a session the trigger cut
    // Each device's recording, in the order the devices were added: the
    // one device's, or each part's (a part ended early included).
    std::vector<FromDevice<RecordingSummary>> parts;
    // The session's automatic verdict: its device's, or its parts' worst
    // (core/storage/AutomaticVerdict.h: partsDecision).
    std::optional<core::Verdict> verdict;
};

// Everything that happened since the last poll().
struct PipelineNews {
    std::vector<FromDevice<std::string>> problems;  // a processor or a limit that cannot run
    std::vector<FromDevice<LinkNotice>> notices;    // what a link noticed (stored as alarms while recording)
    std::vector<FromDevice<LimitAlarm>> alarms;     // limit alarms raised or cleared
    std::optional<TriggerStatus> trigger;           // the trigger's state, when it changed
    std::vector<TriggeredStart> triggered;          // each session the trigger started, in order
    // A device's part that ended while the others record on (its link
    // failed, its disk stopped it): the session of several goes on.
    std::vector<FromDevice<RecordingSummary>> partsEnded;
    std::vector<RecordingEnd> ended;  // recordings that ended by themselves, in order
    // The trigger disarmed itself: the store refused the session it started.
    std::optional<std::string> triggerRefused;

    bool empty() const
    {
        return problems.empty() && notices.empty() && alarms.empty() && !trigger && triggered.empty() &&
               partsEnded.empty() && ended.empty() && !triggerRefused;
    }
};

class LivePipeline {
public:
    // Recordings go into the store at `storePath` (need not exist yet).
    explicit LivePipeline(std::string storePath);
    ~LivePipeline();  // ends a recording as complete, then stops every device

    LivePipeline(const LivePipeline&) = delete;
    LivePipeline& operator=(const LivePipeline&) = delete;

    // A device streaming through a LiveSession of its own on `options` (the
    // pipeline's store path replaces theirs), named `name` or, when empty,
    // after its model unlike the others (partName). Refused while recording
    // or armed (a session keeps the devices it started with) and for a
    // name taken: the reason. Throws std::invalid_argument as LiveSession
    // does (a role for a channel the device lacks).
    std::optional<std::string> add(std::unique_ptr<BlockSource> source, LiveSessionOptions options,
                                   std::string name = {});
    // Takes a device out (it stops); refused while recording or armed.
    std::optional<std::string> remove(std::size_t index);
    void clear();  // every device, after ending a recording as complete
    std::size_t size() const { return m_devices.size(); }
    bool empty() const { return m_devices.empty(); }
    LiveSession& device(std::size_t index) { return *m_devices.at(index).live; }
    const LiveSession& device(std::size_t index) const { return *m_devices.at(index).live; }
    // A device's name in the session (its part's; DEVICE/CHANNEL).
    const std::string& name(std::size_t index) const { return m_devices.at(index).name; }
    std::vector<std::string> names() const;
    // Starts streaming every device not streaming yet.
    void start();
    // Whether any device still streams (or waits to reconnect): false once
    // every link finished or failed for good.
    bool streaming() const;

    // Another store for the next recording and the devices' calibrations;
    // refused while recording: the reason.
    std::optional<std::string> setStorePath(const std::string& path);
    const std::string& storePath() const { return m_storePath; }

    // Records every device with `request`'s metadata: a session of one, or
    // of several with each device its part. Refused (nothing recorded) when
    // any device cannot record, with which one and why, or while armed.
    // Given `length_s`, each device's recording holds that long of its
    // samples (LiveSession::startRecording).
    std::optional<std::string> startRecording(const core::storage::SessionMetadata& request,
                                              std::optional<double> length_s = std::nullopt);
    // Every device's recording of a set length has all of it.
    bool recordingComplete() const;
    std::optional<RecordingEnd> stopRecording();
    bool isRecording() const;
    std::int64_t sessionId() const;  // the session being recorded; 0 when none

    // Hands-free recording (LiveSession::armTrigger) on the only device:
    // refused with several, and while recording.
    std::optional<std::string> armTrigger(const core::trigger::TriggerSettings& settings,
                                          const core::storage::SessionMetadata& request);
    // Disarms; a triggered session open ends as complete.
    std::optional<RecordingEnd> disarmTrigger();
    bool triggerArmed() const;
    TriggerStatus triggerStatus() const;

    PipelineNews poll();

private:
    struct Device {
        std::string name;
        std::unique_ptr<LiveSession> live;
        bool started = false;
        // Its part of the session of several being recorded ended early.
        std::optional<RecordingSummary> endedPart;
    };

    bool several() const { return m_devicesSession != nullptr; }
    std::string tellName(const Device& device) const;
    void pollDevice(Device& device, PipelineNews& news);
    RecordingEnd endOfOne(RecordingSummary summary, bool triggered) const;
    RecordingEnd finishSeveral();

    std::string m_storePath;
    std::vector<Device> m_devices;
    std::unique_ptr<SessionOfDevices> m_devicesSession;  // while recording several devices
    std::optional<TriggerStatus> m_toldTrigger;
};

}  // namespace tactiscope::devices::session
