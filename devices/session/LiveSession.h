// The live-session controller: one connected device and everything that
// happens to its stream, for the GUI's main window and `tactiscope-cli
// record` alike (as PulseView's pv::Session carries acquisition for its
// window). It owns the acquisition, the live buffer the display and the
// wizards read, a unit for each mode the channels feed (LiveModeUnit.h:
// the mode's processor, its zero, its lists), the recorder and the
// recording's metadata, and it has the units move their events and
// readings into the store. Owners only observe it and call poll() now and
// then.
//
// Rules it keeps, so no owner can break them:
// - a mode runs only on channels that can play its roles
//   (core/ModeCapability.h; roles from the device or given in the options
//   or by setRoles()), a source that declares a mode starts in it, and any
//   other device starts in the first mode its channels feed: the general
//   mode, which records any device, at the latest;
// - a recording keeps its mode, profile and calibrations from start to end;
// - a panel-scan recording stores its defects and the automatic verdict, a
//   palpation recording its in-range stiffness readings (with the site),
//   and every recording its profile and the calibrations used;
// - a tare is refused with the reason while the probe is loaded or its
//   signal is not steady (the processors' tare rules), and a processor
//   rebuilt for another profile or calibration goes on from its
//   predecessor's zero: no zero is ever taken under load;
// - what the views show of the session (defects, presses, the site the
//   next press is taken at) is the mode units' lists (unitAs()), on one
//   clock: the recording's while recording, exactly what was stored after
//   the stop, the device's since-connect clock otherwise (lists()).
//
// Threading: every call from one owner thread (the GUI thread, the CLI's
// main loop). The processors run on the acquisition thread; poll() takes
// what they completed.
#pragma once

#include "core/LiveBuffer.h"
#include "core/Vocabulary.h"
#include "core/detector/DetectorParameters.h"
#include "core/modes/ChannelRoles.h"
#include "core/sensors/SensorLimits.h"
#include "core/sensors/SensorProfile.h"
#include "core/signal/SignalChain.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/Recorder.h"
#include "core/storage/RecordingTap.h"
#include "core/trigger/LimitWatch.h"
#include "core/trigger/TriggerMachine.h"
#include "devices/Acquisition.h"
#include "devices/BlockSource.h"
#include "devices/session/LimitAlarms.h"
#include "devices/session/LiveModeUnit.h"
#include "devices/session/LiveRecords.h"
#include "devices/session/ModeInput.h"
#include "devices/session/TriggerGate.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core {
class SinkSlot;
}

namespace tactiscope::devices::session {

struct LiveSessionOptions {
    std::string storePath;  // recordings and calibrations; need not exist yet
    // How much of each processor's output the display may look back on.
    double displaySeconds = 62.0;
    // The sensor profile of each mode that takes one; the built-in one
    // (core/sensors/BuiltInProfiles.h) for a mode not given.
    std::map<core::Mode, core::sensors::SensorProfile> profiles;
    // The recorder's memory bound, in time: a stalled disk beyond it turns
    // into a recorded gap instead of unbounded memory.
    double recorderQueue_s = 30.0;
    // The panel probe's cantilever spacing, which turns the detector's lag
    // into a scan speed and so places defects along the stroke (sites). A
    // panel-scan probe has no profile yet: the paper's prototype's.
    double panelSpacing_m = core::detector::kPrototypeSpacing_m;
    // Roles given to the device's channels by name (core/modes/ChannelRoles.h).
    core::RoleAssignment roles;
    // Recording as one device's part of a session of several
    // (SessionOfDevices): the session, the device's name in it, and the
    // host instant (steadySeconds()) of the session's t = 0, onto which the
    // part's clock is mapped and stored once a second.
    struct PartOfSession {
        std::int64_t session = 0;
        std::string deviceName;
        double start_host_s = 0.0;
    };
    std::optional<PartOfSession> partOf;
    // Filters on channels and math channels (core/signal/SignalSetup.h),
    // run live from the start; none by default.
    core::signal::SignalSetup signal;
};

class LiveSession {
public:
    // Takes the source and builds the processors of every mode its channels
    // can feed; starts in the source's declared mode, else the first mode
    // its channels can feed (general at the latest). Throws
    // std::invalid_argument for a null source, roles naming a channel the
    // device does not have, or a signal setup it cannot run.
    LiveSession(std::unique_ptr<BlockSource> source, LiveSessionOptions options);
    ~LiveSession();  // ends a recording as complete, then stops the device

    LiveSession(const LiveSession&) = delete;
    LiveSession& operator=(const LiveSession&) = delete;

    void start();  // starts streaming
    const BlockSource& source() const { return m_acquisition->source(); }
    // A shunt across channel `channel`'s bridge, and what the device said
    // (BlockSource::requestShunt, takeStatuses; ShuntCheckRun uses them).
    std::optional<std::string> requestShunt(std::size_t channel, bool on)
    {
        return m_acquisition->source().requestShunt(channel, on);
    }
    std::vector<DeviceStatus> takeStatuses() { return m_acquisition->source().takeStatuses(); }
    AcquisitionStats stats() const { return m_acquisition->stats(); }
    // Every channel of the device, for the traces and the wizards.
    std::shared_ptr<const core::LiveBuffer> buffer() const { return m_buffer; }
    // The device's channels with the roles they play, as a recording stores them.
    const std::vector<core::ChannelDescriptor>& channels() const { return m_channels; }
    // Gives the channels roles (replacing those given before; the device's
    // own and the profiles' stay where not overridden) and rebuilds the
    // processors; the mode stays when it can still run, else the default.
    // Refused while recording or for a channel the device lacks: the reason.
    std::optional<std::string> setRoles(core::RoleAssignment roles);
    const core::RoleAssignment& roles() const { return m_options.roles; }

    // The signal setup: a chain on the acquisition thread filters the
    // channels it names and computes its math channels, whose outputs are
    // quantities to watch ("a.filtered", a math channel's name) and to
    // show (signalChain()); with analysisFiltered the modes' processors
    // read the filtered channels. A recording stores the setup with where
    // its filters stood at its first sample, so review computes the same
    // series from the stored samples. Refused while recording or armed,
    // and for a setup the channels or the rate cannot run: the reason.
    std::optional<std::string> setSignal(core::signal::SignalSetup setup);
    const core::signal::SignalSetup& signalSetup() const { return m_options.signal; }
    // The chain running the setup; null when it is empty.
    std::shared_ptr<const core::signal::SignalChain> signalChain() const { return m_chain; }

    // Mode. setMode() returns why it refuses: the mode's channels are
    // missing (one sentence naming them) or a recording is running.
    core::Mode mode() const { return m_mode; }
    // The source's declared mode when its channels feed it, else the first
    // mode they feed (general at the latest).
    core::Mode declaredMode() const;
    std::optional<std::string> refusalOf(core::Mode mode) const;
    std::optional<std::string> setMode(core::Mode mode);

    // Profiles and calibrations. setProfile() refuses a profile of the
    // wrong kind, a probe the model rejects, or any change while recording
    // (of the recording's mode, or of the channels' roles a profile gives);
    // reloadCalibrations() rebuilds a mode's processor on the store's newest
    // calibrations (after a wizard stored one).
    std::optional<std::string> setProfile(core::Mode mode, core::sensors::SensorProfile profile);
    std::optional<std::string> reloadCalibrations(core::Mode mode);
    // Another session store: the next recording goes there and the
    // processors read its calibrations. Refused while recording (a
    // recording keeps its store); the reason, or nothing when done.
    std::optional<std::string> setStorePath(const std::string& path);
    const core::sensors::SensorProfile* profile(core::Mode mode) const;
    const std::vector<core::storage::StoredCalibration>& calibrations(core::Mode mode) const;

    // A mode's unit; null when the channels cannot feed the mode or it has
    // none (general).
    const LiveModeUnit* unit(core::Mode mode) const;
    // A mode's unit by its type (devices/session/modes/<Name>Unit.h), for
    // that mode's own views and tests: what a mode keeps of its own (its
    // processor, its lists, a phantom's grid) is reached through its unit,
    // never through a door of this class. Null when no unit of that type runs.
    template <typename Unit>
    const Unit* unitAs() const
    {
        for (const auto& [mode, unit] : m_units)
            if (const auto* typed = dynamic_cast<const Unit*>(unit.get())) return typed;
        return nullptr;
    }
    template <typename Unit>
    Unit* unitAs()
    {
        return const_cast<Unit*>(std::as_const(*this).unitAs<Unit>());
    }

    // The current mode's zero; nothing when taken, else why not.
    std::optional<std::string> tare();

    // Recording into the store, with `request`'s subject, operator, site and
    // notes; the rest of the metadata is the session's. Returns why it
    // cannot start (the mode cannot run, the store refuses), nothing when
    // it started. Given `length_s`, the recording holds the samples within
    // it of its first (RecordingTap), and then is complete.
    std::optional<std::string> startRecording(const core::storage::SessionMetadata& request,
                                              std::optional<double> length_s = std::nullopt);
    // The same as one device's part of a session of several
    // (SessionOfDevices::partFor), for this recording only.
    std::optional<std::string> startRecordingPart(const core::storage::SessionMetadata& request,
                                                  const LiveSessionOptions::PartOfSession& part,
                                                  std::optional<double> length_s = std::nullopt);
    // A recording of a set length has all of it: stop it now.
    bool recordingComplete() const { return m_recorder && m_tap->complete(); }
    // Ends it as complete, with the automatic verdict in panel scan.
    std::optional<RecordingSummary> stopRecording();
    bool isRecording() const { return m_recorder != nullptr; }
    std::int64_t sessionId() const;  // 0 when not recording
    double sessionTime_s() const;    // of the newest sample recorded
    // The stream time (seconds since connect) of the recording's t = 0;
    // none when not recording or before its first sample.
    std::optional<double> recordingOrigin_s() const;
    core::storage::RecorderStats recorderStats() const;
    const core::storage::SessionMetadata& recordingMetadata() const { return m_metadata; }
    // An operator's marker at a session time; false when not recording.
    bool addMarker(double time_s, const std::string& note);

    // Hands-free recording: armed, the trigger (core/trigger) starts a
    // recording at each start of its condition on a device channel or a
    // quantity of the mode (quantities()), with `pre_s` of the stream
    // before the trigger instant, and ends it `post_s` after; each carries
    // its trigger and a `trigger` event at its instant, and `request`'s
    // metadata with the subject numbered on (door-17, door-18, …). Refused
    // while recording by hand, for a quantity nobody has, or for settings
    // the rules refuse: the reason. Disarming ends an open session as complete.
    std::optional<std::string> armTrigger(const core::trigger::TriggerSettings& settings,
                                          const core::storage::SessionMetadata& request);
    std::optional<RecordingSummary> disarmTrigger();
    bool triggerArmed() const { return m_gate->armed(); }
    TriggerStatus triggerStatus() const { return m_gate->status(); }
    // The triggered sessions ended since the last call, in order.
    std::vector<RecordingSummary> takeTriggeredSummaries() { return std::exchange(m_triggeredSummaries, {}); }
    // Sessions the trigger had cut and that were still waiting for their
    // recorder when it was last disarmed (a store slower than the trigger).
    std::size_t cutNotRecorded() const { return m_cutNotRecorded; }
    // The triggered sessions started since the last call, in order.
    std::vector<TriggeredStart> takeTriggeredStarts() { return std::exchange(m_triggeredStarts, {}); }
    // Why the trigger disarmed itself: the store's refusal of the session
    // a trigger started (every later one would meet the same); taken once.
    std::optional<std::string> takeTriggerRefusal() { return std::exchange(m_triggerRefusal, std::nullopt); }

    // Limit alarms on device channels or quantities of the mode: the
    // probe's own (its profile's, else its sensor model's:
    // core/sensors/SensorLimits.h) and those given here, which replace the
    // probe's on the same quantity and side (LimitSpec::replaces; replacing
    // those given before).
    // Each alarm raised or cleared is told (takeAlarms()), and while
    // recording stored as an `alarm` event from its raise to its clear (or
    // the recording's end) naming its limit. Refused for a quantity nobody
    // has: the reason.
    std::optional<std::string> setLimits(std::vector<core::trigger::LimitSpec> limits);
    // The limits watched, each with where it comes from.
    const std::vector<core::sensors::SensorLimit>& limits() const { return m_effectiveLimits; }
    const std::vector<core::trigger::LimitSpec>& givenLimits() const { return m_givenLimits; }
    // The alarms raised or cleared since the last call, at stream times
    // (seconds since the device connected: one clock for a run of many
    // triggered sessions); and those raised now.
    std::vector<LimitAlarm> takeAlarms() { return std::exchange(m_alarmsTold, {}); }
    const std::vector<LimitAlarm>& raisedAlarms() const { return m_raisedAlarms; }
    // What a trigger or limit may watch: the device's channels, then the
    // current mode's quantities, each with its SI unit and kind.
    std::vector<core::ChannelDescriptor> watchableQuantities() const;
    // An alarm as people read it and the recording keeps it: "a above its
    // warning limit 20 µε (22.2 µε)", "force … 956 µN (978 µN)".
    std::string readableText(const LimitAlarm& alarm) const;
    // A trigger's condition as people read it, in the same units: "a above 20 µε".
    std::string readableText(const core::trigger::TriggerCondition& condition) const;

    // The owner's periodic call: takes the processors' completed defects and
    // presses into the lists below and, while recording, into the store.
    // A recording the disk stopped ends here; its summary is returned.
    std::optional<RecordingSummary> poll();

    // The clock and generation of the lists the mode units keep (see LiveLists).
    const LiveLists& lists() const { return m_lists; }

    // Problems met building the processors (a bad calibration, a probe the
    // model rejects), each one sentence; taken once.
    std::vector<std::string> takeProblems() { return std::exchange(m_problems, {}); }
    // What the link noticed (a device restart, a sequence its clock
    // contradicted), at stream times as the alarms; taken once. While
    // recording, poll() has stored each as an alarm event.
    std::vector<LinkNotice> takeLinkNotices() { return std::exchange(m_linkNotices, {}); }

private:
    std::optional<std::string> build(core::Mode mode, bool inheritZero = true);
    std::shared_ptr<core::signal::SignalChain> makeChain(const core::signal::SignalSetup& setup) const;
    std::optional<std::string> beginRecording(const core::storage::SessionMetadata& request);
    std::optional<QuantityReader> readerFor(const std::string& quantity, std::string& refusal) const;
    void refreshReaders();
    void applyLimits();
    std::vector<core::sensors::SensorLimit> wantedLimits() const;
    void takeTriggered();
    bool startTriggered(const TriggeredSession& pending);
    void takeLimitAlarms();
    void storeAlarm(const LimitAlarm& raised, double end_s);
    void storeWaitingAlarms();
    std::vector<core::ChannelDescriptor> effectiveChannels(const std::vector<core::ChannelDescriptor>& device) const;
    core::RoleAssignment effectiveRoles(const std::vector<core::ChannelDescriptor>& device) const;
    std::optional<std::string> rebuildChannels();
    void buildAll();
    void startLists(LiveClock clock);
    double listTime_s(double streamTime_s) const;
    LiveModeUnit* unitOf(core::Mode mode) const;
    // Each unit's completed results and zeros; `recordingEnds`: the last
    // take of the recording (LiveTake::recordingEnds).
    void takeResults(bool recordingEnds = false);
    // The link's notices are taken at each poll, as a recording begins
    // (what came before is in no session) and as it ends (what waited for
    // its first sample is told however it ended).
    enum class NoticesAt { Poll, RecordingBegins, RecordingEnds };
    void takeNotices(NoticesAt at = NoticesAt::Poll);
    void keepLasting(const LinkNotice& notice);
    void recordStandingFaults();
    void recordUnstoppedEnd(RecordingSummary& summary);
    void storeClockMapping();
    core::storage::RecordingStartFinder startsAt(double host_s) const;
    std::uint64_t recorderQueueBound(double rate_hz, std::size_t channels) const;
    RecordingSummary finishRecording();

    LiveSessionOptions m_options;
    // The session this recording is a part of (m_options.partOf, or
    // startRecordingPart's); none for a session of one device.
    std::optional<LiveSessionOptions::PartOfSession> m_part;
    std::unique_ptr<Acquisition> m_acquisition;
    std::shared_ptr<core::LiveBuffer> m_buffer;
    std::shared_ptr<core::storage::RecordingTap> m_tap;
    bool m_started = false;  // start() was called: the device streams
    std::shared_ptr<TriggerGate> m_gate;
    std::shared_ptr<LimitAlarms> m_limits;
    std::vector<core::ChannelDescriptor> m_deviceChannels;  // the source's, grown as a board's layout grew
    std::vector<core::ChannelDescriptor> m_channels;        // those, with the roles given
    // A slot per mode in the acquisition, made before it streams; a unit
    // rebuilt goes into its mode's slot while the device streams.
    std::map<core::Mode, std::shared_ptr<core::SinkSlot>> m_slots;
    // The signal chain's slot, before the modes' (so a mode may read it);
    // the chain in it, null for none.
    std::shared_ptr<core::SinkSlot> m_signalSlot;
    std::shared_ptr<core::signal::SignalChain> m_chain;
    std::shared_ptr<ModeInput> m_modeInput;  // before every mode's slot
    std::map<core::Mode, std::unique_ptr<LiveModeUnit>> m_units;
    core::Mode m_mode = core::Mode::General;
    std::shared_ptr<core::storage::Recorder> m_recorder;
    core::storage::SessionMetadata m_metadata;  // of the recording
    LiveLists m_lists;
    std::vector<std::string> m_problems;
    std::vector<LinkNotice> m_linkNotices;
    std::vector<LinkNotice> m_noticesWaiting;  // for the recording's first sample, to place them in it
    // The lasting notices since the connection (its latest few), and how
    // many of them the recording under way has seen.
    std::vector<LinkNotice> m_lastingNotices;
    std::size_t m_lastingSeen = 0;
    double m_recordingStartHost_s = 0.0;  // steady clock
    double m_nextClockStore_host_s = 0.0;
    // The trigger armed: its settings and the metadata its sessions take.
    std::optional<core::trigger::TriggerSettings> m_trigger;
    core::storage::SessionMetadata m_triggerRequest;
    unsigned m_triggeredStarted = 0;
    std::vector<RecordingSummary> m_triggeredSummaries;
    std::vector<TriggeredStart> m_triggeredStarts;
    std::size_t m_cutNotRecorded = 0;
    std::optional<std::string> m_triggerRefusal;
    std::vector<core::trigger::LimitSpec> m_givenLimits;
    std::vector<core::sensors::SensorLimit> m_effectiveLimits;
    std::vector<LimitAlarm> m_alarmsTold;
    std::vector<LimitAlarm> m_raisedAlarms;  // as raised: stream times
    // A critical alarm was raised while recording (or is raised at its
    // end): its readings were not true for a while, so it is not judged.
    bool m_criticalWhileRecording = false;
    // Alarms that ended where no recording could mark them yet (stream
    // times): while the trigger was armed and nothing recorded (a session
    // it starts next may reach back over them), or before a recording's
    // first sample was placed (its tap still learning the link's clock).
    struct ClosedAlarm {
        LimitAlarm raised;
        double cleared_s = 0.0;
    };
    std::vector<ClosedAlarm> m_closedAlarmsWaiting;
};

}  // namespace tactiscope::devices::session
