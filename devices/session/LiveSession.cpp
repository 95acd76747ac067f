// LiveSession: the acquisition's sinks, the channels' roles, the mode,
// recording, and the lists and store each poll() fills from the mode
// units. The units are built in LiveSessionProcessors.cpp; the trigger and
// the limit alarms are in LiveSessionWatches.cpp.
#include "devices/session/LiveSession.h"

#include "core/timing/ClockMappingJson.h"

#include "core/ModeCapability.h"
#include "core/SinkSlot.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/RecordingTap.h"
#include "core/text/CountText.h"
#include "devices/SteadyClock.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace tactiscope::devices::session {
namespace {

// How far past a recording's start instant a clock mapping still learning
// the link must have placed the stream before the start is placed by it.
constexpr double kStartSettles_s = 1.0;
// How long after its instant a recording's start may wait for the clock to
// place it, in the host's time: a board catching up on a minute of lines
// sends them within a second, and its clock is no clock until lines come
// on time after them.
constexpr double kLongestStartWait_s = 10.0;

// The lists' generations are numbered across every live session of the
// process: a view bound to another device's session (a new connection)
// never takes its lists for the ones it has drawn.
std::uint64_t nextListGeneration()
{
    static std::atomic<std::uint64_t> generation{0};
    return ++generation;
}

}  // namespace

LiveSession::LiveSession(std::unique_ptr<BlockSource> source, LiveSessionOptions options)
    : m_options(std::move(options))
{
    if (!source) throw std::invalid_argument("a live session needs a source");
    m_deviceChannels = source->channels();
    m_channels = effectiveChannels(m_deviceChannels);
    const double rate_hz = source->nominalSampleRate_hz();
    m_acquisition = std::make_unique<Acquisition>(std::move(source));
    // Two seconds of headroom: the display reads 40 times a second, so only
    // an owner stalled that long loses display samples (never recorded ones).
    m_buffer =
        std::make_shared<core::LiveBuffer>(m_channels.size(), static_cast<std::size_t>(std::ceil(2.0 * rate_hz)) + 1);
    m_acquisition->addSink(m_buffer);
    m_tap = std::make_shared<core::storage::RecordingTap>();
    m_acquisition->addSink(m_tap);
    // The signal chain before the modes, which may read its filtered channels.
    m_signalSlot = std::make_shared<core::SinkSlot>();
    m_acquisition->addSink(m_signalSlot);
    m_modeInput = std::make_shared<ModeInput>();
    m_acquisition->addSink(m_modeInput);
    if (!m_options.signal.empty()) {
        m_chain = makeChain(m_options.signal);
        m_signalSlot->set(m_chain);
        if (m_options.signal.analysisFiltered) m_modeInput->setChain(m_chain);
    }
    // Units rebuilt (another profile, calibration or roles) go into their
    // mode's slot while the device streams.
    for (const auto& definition : core::modeDefinitions()) {
        auto slot = std::make_shared<core::SinkSlot>();
        m_modeInput->add(slot);
        m_slots.emplace(definition.mode, std::move(slot));
    }
    // After the processors: a derived quantity is there for the block just read.
    m_limits = std::make_shared<LimitAlarms>();
    m_acquisition->addSink(m_limits);
    m_gate = std::make_shared<TriggerGate>();
    m_acquisition->addSink(m_gate);
    buildAll();
    m_mode = declaredMode();
    m_lists.generation = nextListGeneration();
    applyLimits();  // the probe's own, from the start
}

// The units of every mode the channels feed, and none of the others.
void LiveSession::buildAll()
{
    for (const auto& [mode, slot] : m_slots) slot->set(nullptr);
    m_units.clear();
    for (const core::Mode mode : core::runnableModes(m_channels))
        if (const auto problem = build(mode, false)) m_problems.push_back(*problem);
}

// The roles the channels play: those the profiles give (to channels the
// device has), under those the owner gave.
core::RoleAssignment LiveSession::effectiveRoles(const std::vector<core::ChannelDescriptor>& device) const
{
    core::RoleAssignment roles;
    const auto give = [&roles](const std::string& channel, core::ChannelRole role) {
        std::erase_if(roles, [role](const auto& given) { return given.second == role; });
        roles[channel] = role;
    };
    for (const auto& [mode, profile] : m_options.profiles)
        for (const auto& [channel, role] : core::sensors::profileRoles(profile))
            if (std::ranges::find(device, channel, &core::ChannelDescriptor::name) != device.end()) give(channel, role);
    for (const auto& [channel, role] : m_options.roles) give(channel, role);
    return roles;
}

// The device's channels with the roles given, and the beams a profile
// scales marked as the counts they are (a board printing plain numbers).
std::vector<core::ChannelDescriptor>
LiveSession::effectiveChannels(const std::vector<core::ChannelDescriptor>& device) const
{
    auto channels = core::applyRoles(device, effectiveRoles(device));
    for (const auto& [mode, profile] : m_options.profiles)
        for (const auto& [name, scale] : core::sensors::profileScales(profile))
            for (auto& channel : channels)
                if (channel.name == name && channel.unit.empty() && channel.kind == core::ChannelKind::Other)
                    channel.unit = "counts";
    return channels;
}

std::optional<std::string> LiveSession::setRoles(core::RoleAssignment roles)
{
    if (isRecording()) return "a recording keeps its channels' roles; stop it first";
    auto previous = std::exchange(m_options.roles, std::move(roles));
    if (auto problem = rebuildChannels()) {
        m_options.roles = std::move(previous);
        return problem;
    }
    return std::nullopt;
}

// The channels again on the roles now given, and every processor on them;
// the mode stays when it can still run. A role for a channel the device
// lacks changes nothing: the reason.
std::optional<std::string> LiveSession::rebuildChannels()
{
    try {
        m_channels = effectiveChannels(m_deviceChannels);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    buildAll();
    if (refusalOf(m_mode)) m_mode = declaredMode();
    refreshReaders();
    startLists(LiveClock::SinceConnect);  // what the old roles found is not this setup's
    return std::nullopt;
}

LiveSession::~LiveSession()
{
    stopRecording();
    m_acquisition->stop();
}

void LiveSession::start()
{
    m_acquisition->start();
    m_started = true;
}

core::Mode LiveSession::declaredMode() const
{
    const auto declared = source().declaredMode();
    if (declared && !refusalOf(*declared)) return *declared;
    return core::runnableModes(m_channels).front();  // general runs on any channels
}

std::optional<std::string> LiveSession::refusalOf(core::Mode mode) const
{
    return core::modeRefusal(mode, m_channels);
}

std::optional<std::string> LiveSession::setMode(core::Mode mode)
{
    if (mode == m_mode) return std::nullopt;
    if (isRecording()) return "the recording keeps its mode; stop it first";
    if (m_trigger) return "the armed trigger records in this mode; disarm it first";
    if (auto refusal = refusalOf(mode)) return refusal;
    m_mode = mode;
    refreshReaders();
    return std::nullopt;
}

std::optional<std::string> LiveSession::tare()
{
    const auto& definition = core::definitionOf(m_mode);
    if (!definition.noZero.empty()) return std::string(definition.noZero);
    if (auto* unit = unitOf(m_mode)) return unit->tare();
    return refusalOf(m_mode).value_or("this mode's processor is not running");
}

std::optional<std::string> LiveSession::startRecording(const core::storage::SessionMetadata& request,
                                                       std::optional<double> length_s)
{
    if (isRecording()) return std::nullopt;
    if (m_trigger) return "the armed trigger starts the recordings; disarm it first";
    m_part = m_options.partOf;
    if (auto error = beginRecording(request)) return error;
    m_tap->attach(m_recorder, startsAt(steadySeconds()), length_s);
    return std::nullopt;
}

std::optional<std::string> LiveSession::startRecordingPart(const core::storage::SessionMetadata& request,
                                                           const LiveSessionOptions::PartOfSession& part,
                                                           std::optional<double> length_s)
{
    if (isRecording()) return std::nullopt;
    if (m_trigger) return "the armed trigger records one device; disarm it first";
    m_part = part;
    if (auto error = beginRecording(request)) {
        m_part.reset();
        return error;
    }
    m_tap->attach(m_recorder, startsAt(part.start_host_s), length_s);  // every part from the session's instant
    return std::nullopt;
}

// A recording begins at a host instant (or, begun before the device
// streams, where its source's stream begins, a part not before its
// session's instant; from its first block when it says none): on the
// source's block time where its clock mapping places
// it. A mapping that states its uncertainty (or is exact) places it at
// once. One still learning the link may rest on
// lines that waited in the port or that a board caught up on once it was
// opened (sent in a burst, their lags fall a period per period): it is
// trusted once it has placed the stream a second past the instant, which
// puts a second of lines on time under it (core/timing/ClockAlignment). A
// mapping that is no clock (steeper than any clock drifts, and not exact) places nothing;
// a source with none, or none within kLongestStartWait_s, records from its
// first block.
core::storage::RecordingStartFinder LiveSession::startsAt(double host_s) const
{
    if (!m_started) {
        const auto streamStart_s = source().streamStart_host_s();
        if (!streamStart_s) return {};
        // A part begins at its session's instant: the devices opened before
        // the last one (a text board is timed for seconds) streamed meanwhile.
        host_s = m_part ? std::max(host_s, *streamStart_s) : *streamStart_s;
    }
    return [source = &source(), host_s](double newestEnd_s, bool mustAnswer) {
        using core::storage::RecordingStart;
        mustAnswer = mustAnswer || steadySeconds() >= host_s + kLongestStartWait_s;
        const auto clock = source->hostClock();
        // An exact mapping is one whatever its slope (a simulator faster than the host).
        const bool exact = clock && clock->basis == core::timing::ClockUncertaintyBasis::Exact;
        if (!clock || (!exact && !(std::abs(clock->drift) < 0.1)))
            return mustAnswer ? RecordingStart::fromFirstBlock() : RecordingStart::notYet();
        const bool settled = clock->basis != core::timing::ClockUncertaintyBasis::TooFewFrames ||
                             clock->host_s(newestEnd_s) >= host_s + kStartSettles_s;
        if (!settled && !mustAnswer) return RecordingStart::notYet();
        const double from_s = clock->device_s(host_s);
        return std::isfinite(from_s) ? RecordingStart::at(from_s) : RecordingStart::fromFirstBlock();
    };
}

// A recording's recorder, metadata, lists and the zero in use, ready for
// its first block (from the tap, or from the trigger's gate).
std::optional<std::string> LiveSession::beginRecording(const core::storage::SessionMetadata& request)
{
    if (auto refusal = refusalOf(m_mode)) return refusal;
    core::storage::SessionMetadata metadata = request;
    metadata.mode = m_mode;
    if (m_part) {
        metadata.partOf = m_part->session;
        metadata.deviceName = m_part->deviceName;
    }
    const DeviceIdentity device = source().identity();
    metadata.deviceModel = device.model;
    metadata.deviceSerial = device.serial;
    metadata.deviceFirmware = device.firmware;
    metadata.profileJson.clear();
    if (const auto* used = profile(m_mode)) metadata.profileJson = core::sensors::toJson(*used);
    metadata.signalSetup = core::signal::signalSetupJson(m_options.signal);
    metadata.calibrationsJson.clear();
    std::vector<std::int64_t> used;
    for (const auto& stored : calibrations(m_mode)) {
        metadata.calibrationsJson += (used.empty() ? "[" : ",") + stored.record.toJson();
        used.push_back(stored.id);
    }
    if (!used.empty()) metadata.calibrationsJson += "]";
    const double rate_hz = source().nominalSampleRate_hz();
    // What the link noticed before belongs to no session (before a
    // triggered one, what came after its first sample belongs in it).
    if (!m_trigger) takeNotices(NoticesAt::RecordingBegins);
    // Nor do the defects and presses found before the record press: taken
    // now, while no recorder would store them. A triggered session's start
    // reaches back: those after its first sample waited for it (takeResults()).
    if (!m_trigger) takeResults();
    try {
        const auto directory = std::filesystem::path(m_options.storePath).parent_path();
        if (!directory.empty()) std::filesystem::create_directories(directory);
        m_recorder = std::make_shared<core::storage::Recorder>(m_options.storePath, metadata, m_channels, rate_hz,
                                                               recorderQueueBound(rate_hz, m_channels.size()), used);
    } catch (const std::exception& e) {  // StorageError, or the folder cannot be made
        return e.what();
    }
    if (m_chain) {
        // Where the filters stood at the recording's first sample goes into
        // its setup, so review computes its filtered series from there.
        std::weak_ptr<core::storage::Recorder> recorder = m_recorder;
        m_recorder->watchFirstSample([chain = m_chain, recorder, setup = m_options.signal](std::uint64_t first) {
            chain->recordingBegins(first, [recorder, setup](core::signal::SignalChain::StartState states) mutable {
                setup.startState = std::move(states);
                if (const auto stored = recorder.lock()) stored->setSignalSetup(core::signal::signalSetupJson(setup));
            });
        });
    }
    m_metadata = std::move(metadata);
    m_lastingSeen = 0;
    startLists(LiveClock::Recording);
    // The zero in use reads the session's first samples; those taken before
    // were dropped above.
    if (auto* unit = unitOf(m_mode)) unit->startRecording(*m_recorder);
    m_recordingStartHost_s = steadySeconds();
    recordStandingFaults();
    return std::nullopt;
}

// The probe's silence before the stop is part of the record: longer than
// a second (or three of its blocks, or of its sample periods) means it was lost and did not come
// back, so the samples to the stop are a gap, with an alarm; a link that
// failed for good says why.
void LiveSession::recordUnstoppedEnd(RecordingSummary& summary)
{
    const auto acquired = m_acquisition->stats();
    const double rate_hz = source().nominalSampleRate_hz();
    const double lastBlock_s =
        std::max(acquired.lastBlockHost_s.value_or(m_recordingStartHost_s), m_recordingStartHost_s);
    const double silence_s = steadySeconds() - lastBlock_s;
    const double blockDuration_s =
        acquired.blocks > 0 ? static_cast<double>(acquired.samples) / static_cast<double>(acquired.blocks) / rate_hz
                            : 0.0;
    std::vector<core::storage::SessionEvent> alarms;
    if (acquired.state == AcquisitionState::Failed) {
        summary.stoppedBecause = acquired.error;
        const double end_s = m_recorder->sessionTime_s();
        alarms.push_back(core::storage::alarmRecord(end_s, end_s, "the link failed: " + acquired.error));
    }
    // A slow board's silence between its lines is no loss: three of its
    // periods (three seconds at one line a second) before it is called lost.
    if (silence_s > std::max({1.0, 3.0 * blockDuration_s, 3.0 / rate_hz})) {
        const double lostAt_s = m_recorder->sessionTime_s();
        summary.lostAt_s = lostAt_s;
        summary.samplesLostAtEnd = static_cast<std::uint64_t>(std::llround(silence_s * rate_hz));
        m_recorder->markLostUntil(lostAt_s + silence_s);
        // A link that failed for good may have found the device back, and
        // not taken it (another device, another rate): not "did not come back".
        const bool refused = acquired.state == AcquisitionState::Failed;
        char text[128];
        std::snprintf(text, sizeof text, "the probe was lost at %.1f s and %s: %.1f s without samples", lostAt_s,
                      refused ? "not taken back" : "did not come back", silence_s);
        alarms.push_back(core::storage::alarmRecord(lostAt_s, lostAt_s + silence_s, text));
    }
    if (!alarms.empty()) m_recorder->addEvents(std::move(alarms));
}

// What the record must carry from before its start: a device that
// contradicted itself still does (the link tells it only now and then: an
// alarm), and a rate that was estimated rather than given (a note: nothing
// went wrong, but every time in the session rests on it).
void LiveSession::recordStandingFaults()
{
    std::vector<core::storage::SessionEvent> alarms;
    const auto counters = source().decoderCounters();
    if (counters.sequenceFaults > 0)
        alarms.push_back(core::storage::alarmRecord(
            0.0, 0.0,
            "before this recording the device's sequence numbers contradicted its clock " +
                std::to_string(counters.sequenceFaults) +
                " times: they are not believed, losses are counted only where its clock agrees"));
    if (const auto rate = source().rateNote()) alarms.push_back(core::storage::noteRecord(0.0, *rate));
    if (!alarms.empty()) m_recorder->addEvents(std::move(alarms));
}

std::optional<RecordingSummary> LiveSession::stopRecording()
{
    if (!isRecording()) return std::nullopt;
    return finishRecording();
}

RecordingSummary LiveSession::finishRecording()
{
    m_tap->detach();
    m_gate->detach();
    if (const auto origin = recordingOrigin_s()) m_lists.origin_s = *origin;
    takeResults(true);  // what completed up to the last recorded block
    takeNotices(NoticesAt::RecordingEnds);
    takeLimitAlarms();
    for (const auto& raised : m_raisedAlarms) storeAlarm(raised, m_recorder->sessionTime_s());
    RecordingSummary summary;
    recordUnstoppedEnd(summary);
    storeClockMapping();
    summary.session = m_recorder->sessionId();
    summary.end_s = m_recorder->sessionTime_s();
    // Past a critical limit the probe's readings stop being true (its
    // limits say so): a recording that went there, as one stopped on a
    // critical alarm mid-stroke did, is not judged automatically.
    const bool pastCritical = std::exchange(m_criticalWhileRecording, false) ||
                              std::ranges::any_of(m_raisedAlarms, [](const LimitAlarm& alarm) {
                                  return alarm.change.severity == core::trigger::LimitSeverity::Critical;
                              });
    if (pastCritical) summary.notJudged = std::string(core::storage::kNotJudged) + "it went past a critical limit";
    const bool whole = !summary.lostAt_s && summary.stoppedBecause.empty() && !pastCritical;
    std::optional<core::storage::VerdictDecision> decision;
    if (auto* unit = unitOf(m_metadata.mode)) decision = unit->finishRecording(summary, whole);
    // A mode that judges says why it did not, for the reviewer too.
    if (!decision && summary.notJudged.empty() && core::definitionOf(m_metadata.mode).detectsDefects) {
        if (summary.lostAt_s) {
            char text[96];
            std::snprintf(text, sizeof text, "the probe was lost at %.1f s and not back by the stop",
                          *summary.lostAt_s);
            summary.notJudged = std::string(core::storage::kNotJudged) + text;
        } else if (!summary.stoppedBecause.empty())
            summary.notJudged = std::string(core::storage::kNotJudged) + summary.stoppedBecause;
    }
    summary.stats = m_recorder->finish(core::SessionStatus::Complete, decision, summary.notJudged);
    if (!summary.stats.error.empty()) summary.verdict.reset();  // the session ended interrupted
    if (const auto* unit = unitOf(m_metadata.mode))
        summary.analysis = unit->storedText(summary);
    else  // a mode with no analysis of its own (general)
        summary.analysis =
            core::text::countText(m_channels.size(), "channel", "channels") + " as they came, no analysis";
    m_recorder.reset();
    m_part.reset();
    m_lists.clock = LiveClock::Recorded;  // the lists hold what was stored, until the next event
    return summary;
}

std::int64_t LiveSession::sessionId() const
{
    return m_recorder ? m_recorder->sessionId() : 0;
}

double LiveSession::sessionTime_s() const
{
    return m_recorder ? m_recorder->sessionTime_s() : 0.0;
}

std::optional<double> LiveSession::recordingOrigin_s() const
{
    return m_recorder ? m_recorder->acquisitionOrigin_s() : std::nullopt;
}

core::storage::RecorderStats LiveSession::recorderStats() const
{
    return m_recorder ? m_recorder->stats() : core::storage::RecorderStats{};
}

bool LiveSession::addMarker(double time_s, const std::string& note)
{
    if (!m_recorder) return false;
    m_recorder->addEvents({core::storage::noteRecord(time_s, note)});
    return true;
}

std::optional<RecordingSummary> LiveSession::poll()
{
    if (const auto origin = recordingOrigin_s()) m_lists.origin_s = *origin;
    takeResults();
    // A board's new layout: its notice (below) says what changed; the
    // buffer and the recording already hold the new channels.
    if (auto grown = m_acquisition->takeGrownChannels()) {
        // The filters and math channels were set on the channels there
        // were: a new one is recorded as it came, which the operator hears.
        if (!m_options.signal.empty())
            for (const auto& channel : *grown)
                if (std::ranges::none_of(m_deviceChannels, [&](const auto& c) { return c.name == channel.name; }))
                    m_problems.push_back(channel.name +
                                         " came after the filters and math channels were set: it is recorded as "
                                         "it came, not filtered; set them again to filter it");
        m_deviceChannels = std::move(*grown);
        m_channels = effectiveChannels(m_deviceChannels);
    }
    takeNotices();
    takeLimitAlarms();
    if (m_recorder && !m_recorder->stats().error.empty()) {
        // The disk stopped it: a trigger would only start the next into the same failure.
        m_gate->disarm();
        m_trigger.reset();
        return finishRecording();
    }
    takeTriggered();
    if (m_part && steadySeconds() >= m_nextClockStore_host_s) {
        m_nextClockStore_host_s = steadySeconds() + 1.0;
        storeClockMapping();
    }
    return std::nullopt;
}

// A part's clock, mapped onto its session's, goes with the record as it
// is found: a recording cut short by a crash keeps the last one.
void LiveSession::storeClockMapping()
{
    if (!m_part || !m_recorder) return;
    const auto clock = source().hostClock();
    const auto origin = m_recorder->acquisitionOrigin_s();
    if (!clock || !origin) return;
    m_recorder->setClockMapping(
        core::timing::toJson(core::timing::onSessionClocks(*clock, *origin, m_part->start_host_s)));
}

// The samples per channel the recorder may hold while the disk is slow:
// recorderQueue_s at the device's rate, but never less than 32 MB of values,
// so a device that claims a far lower rate than it sends (until the link's
// rate check stops it) has its samples kept, not dropped.
std::uint64_t LiveSession::recorderQueueBound(double rate_hz, std::size_t channels) const
{
    constexpr std::uint64_t kMinimumValues = std::uint64_t{1} << 22;
    const auto byRate = static_cast<std::uint64_t>(std::ceil(m_options.recorderQueue_s * rate_hz));
    return std::max(byRate, kMinimumValues / std::max<std::size_t>(channels, 1));
}

// The link's notices are part of the record: a recording keeps each at the
// moment it happened, as an alarm or, where nothing went wrong, a note; one
// from before it is told as such (a board's channel renamed before the
// record press is a channel of holes in the session).
void LiveSession::takeNotices(NoticesAt at)
{
    auto taken = m_acquisition->takeNotices();
    m_noticesWaiting.insert(m_noticesWaiting.end(), std::make_move_iterator(taken.begin()),
                            std::make_move_iterator(taken.end()));
    // Where the recording's first sample lies its tap may not know yet (it
    // holds the blocks while the clock learns the link): until then a
    // notice's moment in it is not known either.
    const auto origin = m_recorder ? m_recorder->acquisitionOrigin_s() : std::nullopt;
    if (m_recorder && !origin && at == NoticesAt::Poll) return;
    const double origin_s = origin.value_or(0.0);
    std::vector<core::storage::SessionEvent> stored;
    for (auto& notice : std::exchange(m_noticesWaiting, {})) {
        if (notice.lasting) keepLasting(notice);
        if (origin && notice.time_s >= origin_s) {
            const double session_s = notice.time_s - origin_s;
            stored.push_back(notice.alarm ? core::storage::alarmRecord(session_s, session_s, notice.text)
                                          : core::storage::noteRecord(session_s, notice.text));
        } else if (m_recorder || at == NoticesAt::RecordingBegins) {
            notice.text += " (before the recording began, so not in it)";
        }
        m_linkNotices.push_back(std::move(notice));
    }
    // What still holds from before the recording, at its start: a channel
    // of holes in it is then explained in it.
    if (m_recorder && origin) {
        for (; m_lastingSeen < m_lastingNotices.size(); ++m_lastingSeen)
            if (const auto& notice = m_lastingNotices[m_lastingSeen]; notice.time_s < origin_s)
                stored.push_back(core::storage::noteRecord(0.0, "before this recording, " + notice.text));
    }
    if (!stored.empty()) m_recorder->addEvents(std::move(stored));
}

// The latest few: a board that changes its layout again and again leaves
// the last changes, which say what it prints now.
void LiveSession::keepLasting(const LinkNotice& notice)
{
    constexpr std::size_t kKept = 8;
    m_lastingNotices.push_back(notice);
    if (m_lastingNotices.size() > kKept) {
        m_lastingNotices.erase(m_lastingNotices.begin());
        m_lastingSeen = m_lastingSeen > 0 ? m_lastingSeen - 1 : 0;
    }
}

// The lists start again: at a record press, at the first event after a
// stop, for other roles.
void LiveSession::startLists(LiveClock clock)
{
    for (const auto& [mode, unit] : m_units) unit->clearLists();
    m_lists.generation = nextListGeneration();
    m_lists.clock = clock;
    m_lists.session = clock == LiveClock::SinceConnect ? 0 : sessionId();
    m_lists.origin_s = 0.0;
}

// A stream time on the lists' clock: the recording's, as stored, while
// recording; since connect otherwise.
double LiveSession::listTime_s(double streamTime_s) const
{
    return m_recorder ? m_recorder->sessionTimeOf(streamTime_s) : streamTime_s;
}

// Each unit's completed results: into the lists, and into the store while
// its mode records; while another mode records, a unit's processor runs on,
// unseen and unstored. After a stop the first new entry starts the lists.
void LiveSession::takeResults(bool recordingEnds)
{
    LiveTake take;
    take.recordingEnds = recordingEnds && m_recorder;
    take.listTime_s = [this](double t_s) { return listTime_s(t_s); };
    take.adding = [this] {
        if (m_lists.clock == LiveClock::Recorded) startLists(LiveClock::SinceConnect);
    };
    if (m_recorder) take.recordingSite = m_metadata.site;
    const auto tell = [this](double time_s, std::string text) { m_linkNotices.push_back({time_s, std::move(text)}); };
    if (m_recorder) {
        take.recordedUntil_s = m_recorder->consumedUntil_s().value_or(-1.0);
        take.recordedFrom_s = m_recorder->acquisitionOrigin_s().value_or(take.recordedFrom_s);
    } else if (const auto reachBack = m_gate->reachBack_s()) {
        // Armed: what a session the trigger is about to start may reach back to waits for it.
        take.recordedUntil_s = *reachBack;
    }
    for (const auto& [mode, unit] : m_units) {
        const bool own = m_recorder && m_metadata.mode == mode;
        take.recorder = own ? m_recorder.get() : nullptr;
        // The operator hears the mode in use, not the others' processors
        // running on unseen (a palpation's zero on a panel's gauges).
        take.tell = mode == (m_recorder ? m_metadata.mode : m_mode) ? LiveTake::Tell(tell) : LiveTake::Tell();
        take.recordingOtherMode = m_recorder && !own;
        unit->take(take);
        unit->takeZeros(take);
    }
}

}  // namespace tactiscope::devices::session
