// RecordOutput: the pipeline's news and the recordings' contract lines.
#include "RecordOutput.h"

#include "CliSupport.h"
#include "core/detector/HumRisk.h"
#include "core/report/DetectorHum.h"
#include "core/storage/SessionStore.h"
#include "core/text/CountText.h"
#include "core/timing/ClockMappingText.h"

#include <QLocale>
#include <QTextStream>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace tactiscope::cli {
namespace {

QString at(double time_s)
{
    return QLocale::c().toString(time_s, 'f', 1);
}

// "NAME: " before what a device of several said; nothing for the only one.
QString from(const std::string& device)
{
    return device.empty() ? QString() : toQString(device) + QStringLiteral(": ");
}

// The samples the store marks lost in each session given, read back;
// none for a store that cannot be read (the caller's count stands).
std::map<std::int64_t, std::uint64_t> storedLosses(const std::string& db, const std::vector<std::int64_t>& sessions)
{
    std::map<std::int64_t, std::uint64_t> lost;
    try {
        core::storage::SessionStore readBack(db, core::storage::Database::Access::ReadOnly);
        for (const std::int64_t session : sessions) {
            lost[session] = 0;
            for (const auto& gap : readBack.gaps(session)) lost[session] += gap.count;
        }
    } catch (const core::storage::StorageError&) {
    }
    return lost;
}

// "2 channels at 500 Hz", "1 channel at 10 Hz".
QString channelsAt(const devices::session::LiveSession& live)
{
    const std::size_t n = live.channels().size();
    return QStringLiteral("%1 %2 at %3 Hz")
        .arg(n)
        .arg(n == 1 ? QStringLiteral("channel") : QStringLiteral("channels"))
        .arg(QLocale::c().toString(live.source().nominalSampleRate_hz()));
}

// "0 CRC errors", "1 CRC error".
QString crcErrorsText(const devices::session::LiveSession& live)
{
    return toQString(core::text::countText(live.source().decoderCounters().crcErrors, "CRC error", "CRC errors"));
}

}  // namespace

RecordOutput::RecordOutput(std::string db, const devices::session::LivePipeline& pipeline,
                           std::optional<core::trigger::TriggerSettings> trigger, bool stopOnCritical)
    : m_db(std::move(db)),
      m_pipeline(pipeline),
      m_trigger(std::move(trigger)),
      m_stopOnCritical(stopOnCritical)
{
}

void RecordOutput::tell(const devices::session::PipelineNews& news)
{
    for (const auto& [device, problem] : news.problems) printError(from(device) + toQString(problem));
    // What the links noticed (stored as alarms), the limits' alarms and the
    // trigger instants, of every device, told in the order they happened
    // on the streams' clock: seconds since record connected, one clock
    // however many sessions a trigger cuts.
    std::vector<std::pair<double, QString>> timed;
    for (const auto& [device, notice] : news.notices)
        timed.emplace_back(
            notice.time_s,
            QStringLiteral("%1at %2 s: %3").arg(from(device), at(notice.time_s), toQString(notice.text)));
    for (const auto& [device, alarm] : news.alarms) {
        const QString severity = QString::fromLatin1(core::trigger::toString(alarm.change.severity));
        const QString text = toQString(m_pipeline.device(deviceIndex(device)).readableText(alarm));
        timed.emplace_back(alarm.time_s,
                           alarm.change.raised
                               ? QStringLiteral("%1at %2 s: %3: %4").arg(from(device), at(alarm.time_s), severity, text)
                               : QStringLiteral("%1at %2 s: cleared: %3").arg(from(device), at(alarm.time_s), text));
        if (m_stopOnCritical && alarm.change.raised && !m_criticalStop &&
            alarm.change.severity == core::trigger::LimitSeverity::Critical)
            m_criticalStop = QStringLiteral("stopped on a critical alarm at %1 s: %2").arg(at(alarm.time_s), text);
    }
    // Every session the trigger started, however many since the last poll.
    for (const auto& start : news.triggered) {
        m_triggered = start.session;
        const QString of =
            m_trigger && m_trigger->sessions ? QStringLiteral(" of %1").arg(*m_trigger->sessions) : QString();
        timed.emplace_back(
            start.trigger_s,
            QStringLiteral("at %1 s: triggered: session %2%3").arg(at(start.trigger_s)).arg(start.session).arg(of));
    }
    std::ranges::stable_sort(timed, {}, &std::pair<double, QString>::first);
    if (!timed.empty() && !std::exchange(m_clockSaid, true))
        printError(QStringLiteral("times below are seconds since record connected; `sessions show` gives each "
                                  "session's events on its own clock"));
    for (const auto& [time_s, line] : timed) printError(line);
    for (const auto& [device, summary] : news.partsEnded)
        printError(QStringLiteral("%1its part ended after %2 s of recording; the other devices record on")
                       .arg(from(device), at(summary.end_s)));
    for (const auto& end : news.ended) report(end);
    // What the trigger does next, after the sessions it ended.
    if (news.trigger)
        if (const auto line = triggerText(*news.trigger)) printError(*line);
    if (news.triggerRefused) {
        printError(QStringLiteral("the trigger could not start a recording: %1; the trigger was disarmed")
                       .arg(toQString(*news.triggerRefused)));
        m_exit = kExitFailure;
    }
}

std::optional<QString> RecordOutput::triggerText(const devices::session::TriggerStatus& status)
{
    if (!m_trigger) return std::nullopt;
    // Its last session started, the trigger waits for nothing more.
    if (m_trigger->sessions && m_triggered >= *m_trigger->sessions) return std::nullopt;
    using core::trigger::TriggerState;
    const QString condition = toQString(m_pipeline.device(0).readableText(m_trigger->condition));
    switch (status.state) {
    case TriggerState::Waiting:  // an edge waits only for its hold-off; a level also for its end
        if (!status.valueSeen)
            return QStringLiteral("trigger waiting for a first value of %1 (none yet: a force has none until its "
                                  "mode's zero is taken)")
                .arg(toQString(m_trigger->condition.quantity));
        return m_trigger->condition.isEdge()
                   ? QStringLiteral("trigger waiting for its hold-off to pass")
                   : QStringLiteral("trigger waiting until %1 no longer holds").arg(condition);
    case TriggerState::Armed:
        return QStringLiteral("trigger armed: %1").arg(condition);
    case TriggerState::Triggered:  // told by each session it started (PipelineNews::triggered)
    case TriggerState::Finished:
        break;
    }
    return std::nullopt;
}

void RecordOutput::report(const devices::session::RecordingEnd& end)
{
    ++m_reported;
    if (end.parts.size() == 1 && end.parts.front().device.empty())
        reportOne(end);
    else
        reportSeveral(end);
}

std::size_t RecordOutput::deviceIndex(const std::string& name) const
{
    if (name.empty()) return 0;
    const auto names = m_pipeline.names();
    return static_cast<std::size_t>(std::ranges::find(names, name) - names.begin());
}

void RecordOutput::reportOne(const devices::session::RecordingEnd& end)
{
    const auto& summary = end.parts.front().what;
    const auto& live = m_pipeline.device(0);
    const auto& written = summary.stats;
    const auto lost = storedLosses(m_db, {summary.session});
    const std::uint64_t lostCount = lost.contains(summary.session)
                                        ? lost.at(summary.session)
                                        : live.stats().samplesLost + written.samplesDropped + summary.samplesLostAtEnd;
    QTextStream(stdout) << "Recorded session " << summary.session << ": "
                        << toQString(core::text::countText(written.samplesWritten, "sample", "samples"))
                        << " per channel, " << lostCount << " lost, " << crcErrorsText(live) << " (" << channelsAt(live)
                        << ", into " << toQString(m_db) << "); "
                        << toQString(core::toString(live.recordingMetadata().mode)) << ": "
                        << toQString(summary.analysis) << Qt::endl;
    tellHoles({}, summary, live.channels());
    tellDetectorHum({}, summary.session);
    tellEndProblem({}, summary);
}

void RecordOutput::reportSeveral(const devices::session::RecordingEnd& end)
{
    std::vector<std::int64_t> parts;
    for (const auto& part : end.parts) parts.push_back(part.what.session);
    const auto lost = storedLosses(m_db, parts);
    std::vector<core::storage::SessionPart> stored;
    try {
        core::storage::SessionStore readBack(m_db, core::storage::Database::Access::ReadOnly);
        stored = readBack.parts(end.session);
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
        m_exit = kExitFailure;
    }
    QTextStream out(stdout);
    out << "Recorded session " << end.session << ": " << m_pipeline.size() << " devices, into " << toQString(m_db)
        << Qt::endl;
    for (const std::string& name : m_pipeline.names()) {
        const auto part = std::ranges::find(end.parts, name,
                                            &devices::session::FromDevice<devices::session::RecordingSummary>::device);
        if (part == end.parts.end()) {
            out << "  " << toQString(name) << ": not recorded" << Qt::endl;
            m_exit = kExitFailure;
            continue;
        }
        const auto& summary = part->what;
        const auto& live = m_pipeline.device(deviceIndex(name));
        const auto clock = std::ranges::find(stored, summary.session, &core::storage::SessionPart::id);
        out << "  " << toQString(name) << " (session " << summary.session
            << "): " << toQString(core::text::countText(summary.stats.samplesWritten, "sample", "samples"))
            << " per channel, "
            << (lost.contains(summary.session) ? lost.at(summary.session) : live.stats().samplesLost) << " lost, "
            << crcErrorsText(live) << " (" << channelsAt(live) << "); "
            << toQString(core::toString(live.recordingMetadata().mode)) << ": " << toQString(summary.analysis)
            << "; clock: " << toQString(core::timing::clockMappingText(clock != stored.end() ? clock->clockJson : ""))
            << Qt::endl;
        tellHoles(name, summary, live.channels());
        tellDetectorHum(name, summary.session);
        tellEndProblem(name, summary);
    }
}

// The values a board sent that were no number ("nan", "inf"), or did not
// send (a channel its new layout no longer prints, one it began to print
// later): stored as holes in their channel, the others' values kept.
void RecordOutput::tellHoles(const std::string& device, const devices::session::RecordingSummary& summary,
                             const std::vector<core::ChannelDescriptor>& channels)
{
    QStringList counts;
    for (std::size_t c = 0; c < std::min(summary.stats.holes.size(), channels.size()); ++c)
        if (summary.stats.holes[c] > 0)
            counts << QStringLiteral("%1 in %2").arg(summary.stats.holes[c]).arg(toQString(channels[c].name));
    if (counts.isEmpty()) return;
    printError(QStringLiteral("%1note: values that were no number (nan, inf) or not printed are stored as holes in "
                              "their channel alone: %2")
                   .arg(from(device), counts.join(QStringLiteral(", "))));
}

// A recording that did not end well: the disk's error, or a probe lost
// and not back by the stop. Either makes the run's exit 1.
void RecordOutput::tellEndProblem(const std::string& device, const devices::session::RecordingSummary& summary)
{
    if (!summary.stats.error.empty()) {
        printError(from(device) + toQString(summary.stats.error));
        m_exit = kExitFailure;
    } else if (summary.lostAt_s) {
        // Not taken back: why follows (the link's error, after the stop).
        printError(QStringLiteral("%1the probe was lost at %2 s and %3; %4 samples kept")
                       .arg(from(device), at(*summary.lostAt_s),
                            summary.stoppedBecause.empty() ? QStringLiteral("did not come back")
                                                           : QStringLiteral("not taken back"))
                       .arg(summary.stats.samplesWritten));
        m_exit = kExitFailure;
    }
}

// A panel scan judged through a hum its detector read unfiltered
// (core/report/DetectorHum.h), from the recording's last seconds: said,
// with what takes it out, as the report says it beside the verdict.
void RecordOutput::tellDetectorHum(const std::string& device, std::int64_t session)
{
    try {
        core::storage::SessionStore store(m_db, core::storage::Database::Access::ReadOnly);
        const auto summary = store.session(session);
        if (!summary || !(summary->sampleRate_hz > 0.0)) return;
        const std::uint64_t end = store.sampleCount(session);
        const auto judged = static_cast<std::uint64_t>(core::detector::kHumJudged_s * summary->sampleRate_hz);
        const auto channels = core::report::channelQuality(store, session, end > judged ? end - judged : 0, end);
        if (const auto hum = core::report::sessionDetectorHum(channels, *summary))
            printError(QStringLiteral("%1note: %2; record with --notch %3 --analyze-filtered, or re-analyse with "
                                      "`analyze --db %4 --session %5 --notch %3`")
                           .arg(from(device), toQString(hum->text))
                           .arg(hum->mains_hz)
                           .arg(toQString(m_db))
                           .arg(session));
    } catch (const core::storage::StorageError&) {
        // The summary's own reading of the store says what is wrong with it.
    }
}

}  // namespace tactiscope::cli
