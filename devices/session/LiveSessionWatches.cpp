// LiveSession's hands-free part (issue 39): what a trigger or a limit can
// watch, arming and disarming the trigger and cutting its sessions, and
// the limit alarms told and stored.
#include "devices/session/LiveSession.h"

#include "core/storage/DefectRecords.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::devices::session {
namespace {

// The quantity of `all` named `name`; Other, without a unit, when none is.
core::ChannelDescriptor named(const std::vector<core::ChannelDescriptor>& all, const std::string& name)
{
    const auto found = std::ranges::find(all, name, &core::ChannelDescriptor::name);
    return found != all.end() ? *found : core::ChannelDescriptor{name, "", core::ChannelKind::Other};
}

}  // namespace

std::vector<core::ChannelDescriptor> LiveSession::watchableQuantities() const
{
    std::vector<core::ChannelDescriptor> watchable = m_channels;
    if (m_chain) watchable.insert(watchable.end(), m_chain->outputs().begin(), m_chain->outputs().end());
    if (const auto* unit = unitOf(m_mode))
        for (const auto& quantity : unit->quantities())
            watchable.push_back({quantity.name, quantity.unit, quantity.kind});
    return watchable;
}

// A device channel by its name, else a quantity of the current mode's
// processor; none, with the names there are, for anything else.
std::optional<QuantityReader> LiveSession::readerFor(const std::string& quantity, std::string& refusal) const
{
    for (std::size_t c = 0; c < m_channels.size(); ++c)
        if (m_channels[c].name == quantity) return QuantityReader::deviceChannel(c, m_channels[c].unit);
    if (m_chain)
        for (std::size_t o = 0; o < m_chain->outputs().size(); ++o)
            if (const auto& output = m_chain->outputs()[o]; output.name == quantity)
                return QuantityReader::derived({output.name, output.unit, output.kind, m_chain->output(), o});
    if (const auto* unit = unitOf(m_mode))
        for (const auto& offered : unit->quantities())
            if (offered.name == quantity) return QuantityReader::derived(offered);
    std::string names;
    for (const auto& watchable : watchableQuantities()) names += (names.empty() ? "" : ", ") + watchable.name;
    refusal = "nothing called '" + quantity + "' to watch: the " + std::string(core::toString(m_mode)) +
              " mode on this device has " + names;
    return std::nullopt;
}

// The trigger and the limits read the processors now running: after a
// processor was rebuilt (another profile, calibration, roles) or the mode
// changed. A quantity gone reads as no value; limits that changed with the
// profile or the mode are set anew.
void LiveSession::refreshReaders()
{
    if (!m_gate) return;  // building the first processors
    std::string ignored;
    if (m_trigger) m_gate->replaceReader(readerFor(m_trigger->condition.quantity, ignored).value_or(QuantityReader()));
    const auto wanted = wantedLimits();
    const auto same = std::ranges::equal(wanted, m_effectiveLimits,
                                         [](const auto& a, const auto& b) { return a.limit.text() == b.limit.text(); });
    if (!same) return applyLimits();
    std::vector<QuantityReader> readers;
    for (const auto& limit : m_effectiveLimits)
        readers.push_back(readerFor(limit.limit.quantity, ignored).value_or(QuantityReader()));
    m_limits->replaceReaders(std::move(readers));
}

// The probe's limits for the current mode, each replaced by one given on
// the same quantity that guards a side in common, then the given ones.
std::vector<core::sensors::SensorLimit> LiveSession::wantedLimits() const
{
    std::vector<core::sensors::SensorLimit> wanted;
    if (const auto* probe = profile(m_mode)) wanted = core::sensors::profileLimits(*probe, m_channels);
    std::erase_if(wanted, [this](const core::sensors::SensorLimit& own) {
        return std::ranges::any_of(m_givenLimits,
                                   [&own](const core::trigger::LimitSpec& given) { return given.replaces(own.limit); });
    });
    for (const auto& given : m_givenLimits) wanted.push_back({given, "given for this session"});
    return wanted;
}

// The limits watched from now on; those raised under the old ones end
// here (stored, while recording). A profile's limit on a quantity this
// device does not have is told as a problem and not watched.
void LiveSession::applyLimits()
{
    if (m_recorder)
        for (const auto& raised : m_raisedAlarms) storeAlarm(raised, m_recorder->sessionTime_s());
    m_raisedAlarms.clear();
    std::vector<LimitAlarms::Watched> watched;
    m_effectiveLimits.clear();
    for (auto& limit : wantedLimits()) {
        std::string refusal;
        auto reader = readerFor(limit.limit.quantity, refusal);
        if (!reader) {
            m_problems.push_back("limit " + limit.limit.text() + " (" + limit.basis + ") is not watched: " + refusal);
            continue;
        }
        watched.push_back({limit.limit, std::move(*reader)});
        m_effectiveLimits.push_back(std::move(limit));
    }
    m_limits->set(std::move(watched), source().nominalSampleRate_hz());
}

std::optional<std::string> LiveSession::armTrigger(const core::trigger::TriggerSettings& settings,
                                                   const core::storage::SessionMetadata& request)
{
    if (isRecording()) return "a recording is running; stop it before arming the trigger";
    if (auto refusal = refusalOf(m_mode)) return refusal;
    std::string refusal;
    auto reader = readerFor(settings.condition.quantity, refusal);
    if (!reader) return refusal;
    try {
        m_gate->arm(settings, std::move(*reader), source().nominalSampleRate_hz(), m_options.recorderQueue_s);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    m_trigger = settings;
    m_triggerRequest = request;
    m_triggerRequest.trigger = core::trigger::settingsText(settings);
    m_triggeredStarted = 0;
    return std::nullopt;
}

std::optional<RecordingSummary> LiveSession::disarmTrigger()
{
    std::optional<RecordingSummary> open;
    if (m_trigger && m_recorder) open = finishRecording();
    m_cutNotRecorded = m_gate->waiting();
    m_gate->disarm();
    m_trigger.reset();
    m_closedAlarmsWaiting.clear();
    return open;
}

// The gate's sessions: one that has had its last sample is finished; one
// that was triggered gets its recorder, its held samples and its trigger
// event. Several a poll: a trigger that re-arms faster than the polls
// loses none of them; but a bounded number, so a store slower than the
// trigger cannot hold the poll (and the stop) for ever: the rest wait.
void LiveSession::takeTriggered()
{
    constexpr int kMostStartsPerPoll = 32;
    if (!m_trigger) return;
    for (int started = 0;; ++started) {
        if (m_gate->takeFinished()) m_triggeredSummaries.push_back(finishRecording());
        if (m_recorder || started == kMostStartsPerPoll) return;
        const auto pending = m_gate->pendingStart();
        if (!pending) {
            // Only what a session the trigger may still start reaches back to is kept.
            const auto reachBack = m_gate->reachBack_s().value_or(std::numeric_limits<double>::infinity());
            std::erase_if(m_closedAlarmsWaiting, [reachBack](const ClosedAlarm& c) { return c.cleared_s < reachBack; });
            return;
        }
        if (!startTriggered(*pending)) return;
    }
}

// A session the gate cut gets its recorder (false when the store refuses:
// the trigger is then disarmed, as every later one would meet the same).
bool LiveSession::startTriggered(const TriggeredSession& pending)
{
    auto request = m_triggerRequest;
    request.subject = core::trigger::numberedSubject(m_triggerRequest.subject, m_triggeredStarted);
    m_part = m_options.partOf;
    if (auto error = beginRecording(request)) {
        m_gate->disarm();
        m_trigger.reset();
        m_triggerRefusal = *error;
        return false;
    }
    ++m_triggeredStarted;
    m_triggeredStarts.push_back({m_triggeredStarted, pending.triggerTime_s});
    m_gate->attach(m_recorder);  // its first samples are in the recorder now: its clock is known
    storeWaitingAlarms();
    core::storage::SessionEvent trigger;
    trigger.kind = core::EventKind::Trigger;
    trigger.start_s = trigger.end_s = m_recorder->sessionTimeOf(pending.triggerTime_s);
    trigger.note = m_trigger->condition.text();
    m_recorder->addEvents({trigger});
    return true;
}

std::optional<std::string> LiveSession::setLimits(std::vector<core::trigger::LimitSpec> limits)
{
    for (const auto& limit : limits) {
        std::string refusal;
        if (!readerFor(limit.quantity, refusal)) return refusal;
        try {
            core::trigger::LimitWatch check(limit, source().nominalSampleRate_hz());
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
    }
    m_givenLimits = std::move(limits);
    applyLimits();
    return std::nullopt;
}

// Each alarm raised or cleared: told on the stream's clock (one that does
// not start again with each session a trigger cuts); a clear stores the
// alarm, from its raise, into the recording.
void LiveSession::takeLimitAlarms()
{
    const bool placed = m_recorder && m_recorder->acquisitionOrigin_s();
    if (placed) storeWaitingAlarms();
    for (auto alarm : m_limits->take()) {
        const auto same = [&alarm](const LimitAlarm& raised) {
            return raised.change.severity == alarm.change.severity && raised.limit.text() == alarm.limit.text();
        };
        if (alarm.change.raised) {
            if (m_recorder && alarm.change.severity == core::trigger::LimitSeverity::Critical)
                m_criticalWhileRecording = true;
            m_raisedAlarms.push_back(alarm);
        } else if (const auto raised = std::ranges::find_if(m_raisedAlarms, same); raised != m_raisedAlarms.end()) {
            if (placed)
                storeAlarm(*raised, m_recorder->sessionTimeOf(alarm.time_s));
            else if (m_recorder || m_trigger)  // the recording's first sample, or the next session's, may be before it
                m_closedAlarmsWaiting.push_back({*raised, alarm.time_s});
            m_raisedAlarms.erase(raised);
        }
        m_alarmsTold.push_back(std::move(alarm));
    }
}

// The alarms raised and cleared before the recording's first sample was
// placed, from samples it holds: a triggered session's (its pre-trigger
// time, the stroke that triggered it), or a recording whose tap held its
// first blocks while the link's clock was learnt. Stored in it as they
// would have been had it been placed at once; those from before its first
// sample are forgotten.
void LiveSession::storeWaitingAlarms()
{
    const auto origin = m_recorder->acquisitionOrigin_s();
    for (const auto& closed : std::exchange(m_closedAlarmsWaiting, {}))
        if (origin && closed.cleared_s >= *origin)
            storeAlarm(closed.raised, m_recorder->sessionTimeOf(closed.cleared_s));
}

// An alarm as the recording keeps it: from its raise (or the recording's
// start) to `end_s`, naming its limit.
void LiveSession::storeAlarm(const LimitAlarm& raised, double end_s)
{
    if (!m_recorder->acquisitionOrigin_s()) return;  // before the first sample there is nothing to mark
    const double start_s = std::max(0.0, m_recorder->sessionTimeOf(raised.time_s));
    if (start_s > end_s) return;  // raised after the recording's last sample
    // A critical alarm over the recording's samples, however it came (a
    // triggered session's pre-trigger stroke included), leaves it unjudged.
    if (raised.change.severity == core::trigger::LimitSeverity::Critical) m_criticalWhileRecording = true;
    // The limit as it was given, besides.
    m_recorder->addEvents(
        {core::storage::alarmRecord(start_s, end_s, readableText(raised) + "; limit " + raised.limit.text())});
}

std::string LiveSession::readableText(const core::trigger::TriggerCondition& condition) const
{
    const auto quantity = named(watchableQuantities(), condition.quantity);
    const auto wording = core::trigger::readableWording(quantity.kind, quantity.unit,
                                                        std::max(std::abs(condition.level), std::abs(condition.high)));
    return condition.readableText(wording.level, wording.unit);
}

std::string LiveSession::readableText(const LimitAlarm& alarm) const
{
    const auto level = alarm.limit.level(alarm.change.severity).value_or(core::trigger::LimitLevel());
    return alarm.change.text(
        alarm.limit, core::trigger::readableWording(named(watchableQuantities(), alarm.limit.quantity).kind, alarm.unit,
                                                    std::max(std::abs(level.low), std::abs(level.high))));
}

}  // namespace tactiscope::devices::session
