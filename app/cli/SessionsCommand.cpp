// The sessions subcommand: list, show, export, verdict, delete and upgrade.
#include "SessionsCommand.h"

#include "CliSupport.h"
#include "ExportMath.h"
#include "SessionArgument.h"
#include "core/derived/SessionLanes.h"
#include "core/detector/DefectOrder.h"
#include "core/modes/ModeDefinition.h"
#include "core/report/VerdictTrail.h"
#include "core/sensors/SensorProfile.h"
#include "core/signal/SignalColumns.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/OpenSessionSource.h"
#include "core/storage/Schema.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionSource.h"
#include "core/storage/SessionStore.h"
#include "core/storage/StoredSites.h"
#include "core/text/JsonWriter.h"
#include "core/timing/ClockMappingText.h"

#include <QLocale>
#include <QTextStream>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

namespace tactiscope::cli {
namespace {

using core::storage::SessionSource;
using core::storage::SessionSummary;
using core::storage::StorageError;

// The scales the session's profile gives channels a board sent as counts
// (none when it has no profile, or one this version cannot read).
core::sensors::ChannelScales profileScalesOf(const std::string& profileJson)
{
    if (profileJson.empty()) return {};
    try {
        return core::sensors::profileScales(core::sensors::parseSensorProfile(profileJson, "the session's"));
    } catch (const core::sensors::ProfileError&) {
        return {};
    }
}

// A stored text on one line of a table: a newline or another control
// character in a subject would otherwise start a row of its own.
QString oneCell(const std::string& text)
{
    QString cell;
    for (const QChar c : toQString(text)) {
        if (c == QLatin1Char('\n'))
            cell += QStringLiteral("\\n");
        else if (c == QLatin1Char('\t'))
            cell += QStringLiteral("\\t");
        else if (c.category() == QChar::Other_Control)
            cell += QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
        else
            cell += c;
    }
    return cell;
}

// The verdict in a list's column: "pass", "defects found", "not judged"
// (its mode judges but did not: `show` says why), or "—".
QString verdictCell(const core::storage::SessionSummary& s)
{
    if (s.verdict) return toQString(core::verdictText(s.verdict));
    return s.unjudged.empty() ? QStringLiteral("—") : QStringLiteral("not judged");
}

// The list's length when no --limit or --all says: a screenful or two,
// whatever the store's size (a central store holds millions).
constexpr std::size_t kDefaultListed = 100;

// One page of the list (`filter.limit` of them; 0: all); a note on
// standard error says how to go on when more match.
int list(SessionSource& store, core::storage::SessionFilter filter, bool json)
{
    const std::size_t page = filter.limit;
    if (page > 0) filter.limit = page + 1;  // one more: whether there are more
    auto sessions = store.sessions(filter);
    const bool more = page > 0 && sessions.size() > page;
    if (more) {
        sessions.resize(page);
        std::cerr << "note: more sessions match: --after " << sessions.back().id << " lists the next " << page
                  << ", --limit N more at once, --all every one\n";
    }
    if (json) {
        core::text::JsonWriter out;
        out.beginArray();
        for (const auto& s : sessions) {
            out.beginObject();
            out.key("id").value(static_cast<long long>(s.id));
            out.key("uuid").value(s.uuid);
            out.key("mode").value(core::toString(s.metadata.mode));
            out.key("subject").value(s.metadata.subject);
            out.key("operator").value(s.metadata.operatorName);
            out.key("started_utc").value(s.startedUtc);
            out.key("status").value(core::toString(s.status));
            out.key("verdict").value(core::verdictText(s.verdict));
            if (!s.unjudged.empty()) out.key("unjudged").value(s.unjudged);  // why its mode gave none
            out.key("duration_s").value(s.duration_s());
            out.key("events").value(static_cast<long long>(s.eventCount));  // its parts' too
            if (!s.station.empty()) out.key("station").value(s.station);    // a central store's
            out.endObject();
        }
        out.endArray();
        std::cout << out.str() << '\n';
        return kExitOk;
    }
    QTextStream out(stdout);
    if (sessions.empty()) {
        out << "No sessions.\n";
        return kExitOk;
    }
    // A central store's sessions say where each was recorded.
    int stationWidth = 0;
    for (const auto& s : sessions) stationWidth = std::max(stationWidth, static_cast<int>(oneCell(s.station).size()));
    if (stationWidth > 0) stationWidth = std::max(stationWidth, 7) + 2;
    const auto stationCell = [stationWidth](const QString& text) {
        return stationWidth > 0 ? text.leftJustified(stationWidth) : QString();
    };
    out << qSetFieldWidth(6) << Qt::right << "id" << qSetFieldWidth(0) << "  " << stationCell(QStringLiteral("station"))
        << QString("started (UTC)").leftJustified(26) << QString("mode").leftJustified(11)
        << QString("status").leftJustified(12) << QString("verdict").leftJustified(14)
        << QString("duration").rightJustified(10) << "  subject / operator\n";
    for (const auto& s : sessions) {
        out << qSetFieldWidth(6) << Qt::right << s.id << qSetFieldWidth(0) << "  " << stationCell(oneCell(s.station))
            << toQString(s.startedUtc).leftJustified(26) << toQString(core::toString(s.metadata.mode)).leftJustified(11)
            << toQString(core::toString(s.status)).leftJustified(12) << verdictCell(s).leftJustified(14)
            << (QString::number(s.duration_s(), 'f', 1) + QStringLiteral(" s")).rightJustified(10) << "  "
            << oneCell(s.metadata.subject)
            << (s.metadata.operatorName.empty() ? QString() : " / " + oneCell(s.metadata.operatorName)) << '\n';
    }
    return kExitOk;
}

std::size_t eventCount(SessionSource& store, std::int64_t id)
{
    std::size_t count = 0;
    for (const auto& analysis : store.analyses(id)) count += store.events(id, analysis).size();
    return count;
}

// A session's events by the analysis that found them: "8 live, 3 offline",
// or "none".
std::string eventsText(SessionSource& store, std::int64_t id)
{
    QStringList analyses;
    for (const auto& analysis : store.analyses(id))
        if (const auto count = store.events(id, analysis).size(); count > 0)
            analyses << QStringLiteral("%1 %2").arg(count).arg(toQString(analysis));
    return analyses.isEmpty() ? std::string("none") : analyses.join(QStringLiteral(", ")).toStdString();
}

// The first of a session's live events, a line each under its count: when
// (its span on the session's clock), what, and its order or note; the rest
// are counted ("export --format json" has them all).
void listEvents(QTextStream& out, const std::vector<core::storage::SessionEvent>& events)
{
    constexpr std::size_t kShown = 20;
    const auto seconds = [](double t_s) { return QLocale::c().toString(t_s, 'f', 3); };
    for (std::size_t i = 0; i < std::min(events.size(), kShown); ++i) {
        const auto& e = events[i];
        QString what = e.kind == core::EventKind::Defect
                           ? QString::fromLatin1(core::detector::defectOrderText(e.direction))
                           : toQString(e.note);
        if (e.kind == core::EventKind::Defect && e.peakR)
            what += QStringLiteral(", R %1").arg(QLocale::c().toString(*e.peakR, 'f', 2));
        const QString when =
            e.end_s > e.start_s ? seconds(e.start_s) + QStringLiteral("–") + seconds(e.end_s) : seconds(e.start_s);
        out << QString(18, QLatin1Char(' ')) << (when + QStringLiteral(" s")).leftJustified(18) << ' '
            << toQString(core::toString(e.kind)).leftJustified(8) << ' ' << oneCell(what.toStdString()) << '\n';
    }
    if (events.size() > kShown)
        out << QString(18, QLatin1Char(' '))
            << QStringLiteral("… and %1 more (export --format json lists them all)").arg(events.size() - kShown)
            << '\n';
}

// The readings under their count, as the events are listed: when, what,
// the value with its standard uncertainty, where, and whose when not the
// recording's own (a saved re-analysis).
void listReadings(QTextStream& out, const std::vector<core::storage::SessionReading>& readings)
{
    constexpr std::size_t kShown = 20;
    const auto seconds = [](double t_s) { return QLocale::c().toString(t_s, 'f', 3); };
    for (std::size_t i = 0; i < std::min(readings.size(), kShown); ++i) {
        const auto& r = readings[i];
        QString what = toQString(r.quantity) + QLatin1Char(' ') + QLocale::c().toString(r.value, 'g', 6);
        if (r.standardError) what += QStringLiteral(" ± ") + QLocale::c().toString(*r.standardError, 'g', 2);
        what += QLatin1Char(' ') + toQString(r.unit);
        if (!r.site.empty()) what += QStringLiteral(" at ") + toQString(r.site);
        if (r.analysis != core::storage::kLiveAnalysis) what += QStringLiteral(" (%1)").arg(toQString(r.analysis));
        out << QString(18, QLatin1Char(' '))
            << (seconds(r.start_s) + QStringLiteral("–") + seconds(r.end_s) + QStringLiteral(" s")).leftJustified(18)
            << ' ' << oneCell(what.toStdString()) << '\n';
    }
    if (readings.size() > kShown)
        out << QString(18, QLatin1Char(' '))
            << QStringLiteral("… and %1 more (export --format json lists them all)").arg(readings.size() - kShown)
            << '\n';
}

int show(SessionSource& store, std::int64_t id, bool json)
{
    if (json) {
        core::storage::writeSessionMetadataJson(store, id, std::cout);
        return kExitOk;
    }
    const auto s = *store.session(id);
    QTextStream out(stdout);
    const auto line = [&](const char* name, const std::string& value) {
        out << QString(name).leftJustified(18) << (value.empty() ? QStringLiteral("—") : oneCell(value)) << '\n';
    };
    line("id", std::to_string(s.id));
    line("uuid", s.uuid);
    // On a central store: where it was recorded, and its id there.
    if (!s.station.empty()) line("station", s.station + " (id " + std::to_string(s.stationId) + " there)");
    line("mode", std::string(core::toString(s.metadata.mode)));
    line("subject", s.metadata.subject);
    line("operator", s.metadata.operatorName);
    line("site", s.metadata.site);
    line("notes", s.metadata.notes);
    line("started (UTC)", s.startedUtc);
    line("ended (UTC)", s.endedUtc);
    line("status", std::string(core::toString(s.status)));
    if (!s.metadata.trigger.empty()) line("trigger", s.metadata.trigger);
    if (!s.metadata.signalSetup.empty()) line("signal", core::signal::signalSetupText(s.metadata.signalSetup));
    if (s.metadata.partOf != 0)  // one device's part: the session it belongs to
        line("part of", "session " + std::to_string(s.metadata.partOf) + " (device " + s.metadata.deviceName + ")");
    // No verdict: why, when its mode would have judged it.
    line("verdict", s.verdict || s.unjudged.empty() ? std::string(core::verdictText(s.verdict)) : s.unjudged);
    if (s.verdict && !s.unjudged.empty()) line("", "  " + core::report::unjudgedTrailLine(s.unjudged));
    for (const auto& decision : core::report::verdictTrailLines(store.verdicts(id))) line("", "  " + decision);
    // One device's identity, samples and channels: the session's own, or
    // each part's for a session of several devices.
    const auto device = [&](const core::storage::SessionMetadata& m, std::int64_t of) {
        line("device", m.deviceModel + (m.deviceSerial.empty() ? "" : " " + m.deviceSerial));
        line("firmware", m.deviceFirmware);
        std::uint64_t lost = 0;
        for (const auto& gap : store.gaps(of)) lost += gap.count;
        const auto channels = store.channels(of);
        const auto own = store.session(of);
        // As `record` said it: the samples there are, then those lost, over the span of both.
        const std::uint64_t spanned = store.sampleCount(of);
        out << QString("samples").leftJustified(18) << (spanned - std::min(lost, spanned)) << " per channel, " << lost
            << " lost (" << QString::number(own ? own->duration_s() : 0.0, 'f', 3) << " s)\n";
        out << QString("channels").leftJustified(18);
        const auto scales = profileScalesOf(m.profileJson);
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const auto& d = channels[c].descriptor;
            const auto scale = core::isCounts(d.unit) ? scales.find(d.name) : scales.end();
            out << (c ? ", " : "") << toQString(d.name) << " ["
                << (d.unit.empty() ? toQString(core::toString(d.kind)) : toQString(d.unit))
                << (scale != scales.end() ? ", " + toQString(core::sensors::scaleText(scale->second)) : QString())
                << "]";
            if (d.role) out << " as " << toQString(core::toString(*d.role));
        }
        if (!channels.empty()) out << " at " << channels.front().sampleRate_hz << " Hz";
        out << '\n';
    };
    // A panel scan's defects at their sites, each placed with its ± and
    // how (core/storage/StoredSites.h), as `--json` gives them.
    const auto sites = [&](std::int64_t of) {
        const auto defects = core::storage::defectEventsOf(store.events(of));
        if (defects.empty()) return;
        const auto grouping = core::storage::storedSites(store, of, defects);
        line("sites", std::to_string(grouping.sites.size()) + " (" + grouping.method + ")");
        for (std::size_t i = 0; i < grouping.sites.size(); ++i)
            line("", "  " + std::to_string(i + 1) + ": " + core::detector::siteText(grouping.sites[i]));
    };
    const auto parts = store.parts(id);
    if (parts.empty()) device(s.metadata, id);
    std::size_t partEvents = 0;
    line("recorded by", "Tactiscope " + s.appVersion);
    for (const auto& part : parts) {
        out << '\n';
        line("part", part.deviceName + " (session " + std::to_string(part.id) + ", " +
                         std::string(core::toString(part.status)) + ")");
        const auto own = store.session(part.id);
        if (own) device(own->metadata, part.id);
        if (own && !own->metadata.signalSetup.empty())
            line("signal", core::signal::signalSetupText(own->metadata.signalSetup));
        line("clock", core::timing::clockMappingText(part.clockJson));
        line("events", eventsText(store, part.id));
        listEvents(out, store.events(part.id));
        sites(part.id);
        const auto partReadings = store.readings(part.id);
        line("readings", std::to_string(partReadings.size()));
        listReadings(out, partReadings);
        partEvents += eventCount(store, part.id);
    }
    if (!parts.empty()) out << '\n';
    // A session of several devices keeps its events in its parts.
    line("events", parts.empty() ? eventsText(store, id)
                                 : std::to_string(eventCount(store, id) + partEvents) + " with its parts'");
    if (parts.empty()) {
        listEvents(out, store.events(id));
        sites(id);
    }
    const auto readings = store.readings(id);
    line("readings", std::to_string(readings.size()));
    listReadings(out, readings);
    line("annotations", std::to_string(store.annotations(id).size()));
    return kExitOk;
}

// A verdict as the command line writes it: "pass" or "defects-found" (the
// stored "defects found" too), for `verdict` and `list --verdict` alike.
std::optional<core::Verdict> verdictArgument(const QString& word)
{
    return core::verdictFromString(QString(word).trimmed().replace(QLatin1Char('-'), QLatin1Char(' ')).toStdString());
}

// A reviewer's verdict, added to the session's trail.
int decideVerdict(SessionSource& store, std::int64_t id, const QString& word, const QString& by, const QString& note)
{
    const auto verdict = verdictArgument(word);
    if (!verdict) {
        printError(QStringLiteral("the verdict must be pass or defects-found, not %1").arg(quoted(word)));
        return kExitUsage;
    }
    const auto session = store.session(id);
    if (!core::definitionOf(session->metadata.mode).detectsDefects) {
        printError(QStringLiteral("session %1 is a %2 session: only a panel scan has a verdict")
                       .arg(id)
                       .arg(toQString(core::toString(session->metadata.mode))));
        return kExitUsage;
    }
    if (session->status == core::SessionStatus::Recording) {
        printError(QStringLiteral("session %1 is still being recorded: its verdict is decided when it stops").arg(id));
        return kExitUsage;
    }
    core::storage::VerdictDecision decision;
    decision.role = core::VerdictRole::Reviewer;
    decision.verdict = *verdict;
    decision.decidedBy = by.trimmed().toStdString();
    decision.note = note.trimmed().toStdString();
    store.decideVerdict(id, decision);
    const auto trail = core::report::verdictTrailLines(store.verdicts(id));
    QTextStream(stdout) << "Session " << id << ": " << toQString(trail.back()) << '\n';
    return kExitOk;
}

int exportSession(SessionSource& store, std::int64_t id, const QString& format, const QString& output, bool derived,
                  const QStringList& math)
{
    std::unique_ptr<core::storage::ComputedColumns> computed;
    if (derived) {
        try {
            computed = core::derived::computedColumns(store, *store.session(id));
        } catch (const std::invalid_argument& e) {
            printError(QStringLiteral("--derived: %1").arg(toQString(e.what())));
            return kExitUsage;
        }
    }
    // The filtered and math channels the session recorded, as it showed them
    // live; a session of several devices, each part's own.
    core::storage::PartColumns partColumns;
    std::vector<std::string> problems;
    if (format == QLatin1String("csv")) {
        std::string problem;
        computed = core::signal::withRecordedSignal(store, id, std::move(computed), problem);
        if (!problem.empty()) problems.push_back(problem);
        partColumns = core::signal::recordedSignalOfParts(store, problems);
    }
    if (const auto refusal = addExportMath(store, id, math, computed, partColumns)) {
        printError(*refusal);
        return kExitUsage;
    }
    try {
        core::storage::exportSession(store, id,
                                     format == QLatin1String("csv") ? core::storage::ExportFormat::Csv
                                                                    : core::storage::ExportFormat::Json,
                                     output.toStdString(), {}, computed.get(), partColumns);
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e);
    }
    for (const auto& problem : problems) printError(toQString(problem));
    return kExitOk;
}

// Brings a station's store to this build's version in place (readers of an
// older store read it through a private copy until then).
int upgradeStore(const QString& db)
{
    if (core::storage::isCentralStoreAddress(db.toStdString())) {
        printError(QStringLiteral("a central store is brought up to date by `tactiscope-cli server init`"));
        return kExitUsage;
    }
    try {
        const core::storage::SessionStore store(db.toStdString());
        printStoreNote(store);
        QTextStream out(stdout);
        out << db << ": store version " << core::storage::kSchemaVersion;
        if (store.versionFound() < core::storage::kSchemaVersion)
            out << " (updated from version " << store.versionFound() << ")\n";
        else
            out << ", already up to date\n";
    } catch (const StorageError& e) {
        return storageFailure(e);
    }
    return kExitOk;
}

}  // namespace

int runSessions(const QStringList& arguments)
{
    const QString name = QStringLiteral("sessions");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Inspect a session store.\n"
        "  list                     the sessions, newest first, 100 at a time (filters: --mode, --subject,\n"
        "                           --operator, --verdict, --status, --station, --from, --before, --search;\n"
        "                           pages: --limit, --after, --all)\n"
        "  show ID|UUID|last        one session's metadata, channels and losses\n"
        "  export ID|UUID|last --format csv|json --output PATH [--derived] [--math NAME[UNIT]=EXPR]...\n"
        "                           CSV: t then the channels (metadata in PATH's .meta.json); JSON: all;\n"
        "                           --derived (CSV): the mode's physical quantities too (palpation:\n"
        "                           force_high [N], force_low [N], Q, stiffness [N/m]; capacitive:\n"
        "                           delta_c [F], relative_change, force [N], deflection [m]);\n"
        "                           --math (CSV): a math channel in its unit, \"diff[µε]=a - b\"\n"
        "  verdict ID|UUID|last pass|defects-found --by NAME [--note TEXT]\n"
        "                           a reviewer's verdict, added to the session's verdict trail\n"
        "  delete ID|UUID           remove a session and its samples\n"
        "  upgrade                  bring an older store to this version in place (readers read an\n"
        "                           older store through a private updated copy until then)\n"
        "A session is named by its id in this store, its uuid (the same in every store) or 'last'."));
    parser.addPositionalArgument(QStringLiteral("action"),
                                 QStringLiteral("list, show, export, verdict, delete or upgrade."));
    parser.addOptions({
        {QStringLiteral("db"),
         QStringLiteral("The session store (required): a station's file, or a central store's connection string "
                        "(postgresql://… or key=value with host= or dbname=)."),
         QStringLiteral("FILE|CONNINFO")},
        {QStringLiteral("json"), QStringLiteral("list, show: print JSON.")},
        {QStringLiteral("format"), QStringLiteral("export: csv or json."), QStringLiteral("csv|json")},
        {QStringLiteral("output"), QStringLiteral("export: the file to write."), QStringLiteral("PATH")},
        {QStringLiteral("derived"), QStringLiteral("export (CSV): add the mode's physical quantities.")},
        {QStringLiteral("math"),
         QStringLiteral("export (CSV): add a math channel over the channels, NAME[UNIT]=EXPR, e.g. "
                        "\"diff[µε]=a - b\" (repeatable; each may use those before it; units are checked). A "
                        "channel the recording filtered is read filtered, as its own math channels read it. A "
                        "session of several devices: DEVICE/NAME[UNIT]=EXPR, over that device's channels."),
         QStringLiteral("NAME[UNIT]=EXPR")},
        {QStringLiteral("mode"), QStringLiteral("list: only this mode."), QStringLiteral("MODE")},
        {QStringLiteral("subject"), QStringLiteral("list: only this panel or phantom."), QStringLiteral("ID")},
        {QStringLiteral("operator"), QStringLiteral("list: only this operator."), QStringLiteral("NAME")},
        {QStringLiteral("verdict"), QStringLiteral("list: only this verdict: pass or defects-found."),
         QStringLiteral("VERDICT")},
        {QStringLiteral("status"), QStringLiteral("list: only this status: complete, interrupted or recording."),
         QStringLiteral("STATUS")},
        {QStringLiteral("station"), QStringLiteral("list (a central store): only the sessions of this station."),
         QStringLiteral("NAME")},
        {QStringLiteral("from"), QStringLiteral("list: started on or after (UTC, e.g. 2026-11-21)."),
         QStringLiteral("DATE")},
        {QStringLiteral("before"), QStringLiteral("list: started before (UTC)."), QStringLiteral("DATE")},
        {QStringLiteral("search"),
         QStringLiteral("list: text in subject, operator, site, notes, verdict (or why none) or serial."),
         QStringLiteral("TEXT")},
        {QStringLiteral("limit"),
         QStringLiteral("list: at most N sessions (default 100; a note on standard error says when more match)."),
         QStringLiteral("N")},
        {QStringLiteral("after"), QStringLiteral("list: the next page, the sessions listed after session ID."),
         QStringLiteral("ID")},
        {QStringLiteral("all"), QStringLiteral("list: every session that matches, however many.")},
        {QStringLiteral("by"), QStringLiteral("verdict: who decides it (required)."), QStringLiteral("NAME")},
        {QStringLiteral("note"), QStringLiteral("verdict: why."), QStringLiteral("TEXT")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usageError(QStringLiteral("say what to do: list, show, export, verdict, delete or upgrade"), usage);
    const QString action = positional.front();
    const bool decides = action == QLatin1String("verdict");
    const bool takesId = action == QLatin1String("show") || action == QLatin1String("export") ||
                         action == QLatin1String("delete") || decides;
    const bool takesNone = action == QLatin1String("list") || action == QLatin1String("upgrade");
    if (!takesNone && !takesId) return usageError(QStringLiteral("unknown action %1").arg(quoted(action)), usage);
    if (decides && positional.size() != 3)
        return usageError(
            QStringLiteral("verdict needs a session and a verdict: verdict ID|UUID|last pass|defects-found"), usage);
    if (!decides && positional.size() != (takesId ? 2 : 1))
        return usageError(takesId ? QStringLiteral("%1 needs one session: ID, UUID or last").arg(action)
                                  : QStringLiteral("%1 takes no session").arg(action),
                          usage);
    if (decides && parser.value(QStringLiteral("by")).trimmed().isEmpty())
        return usageError(QStringLiteral("verdict needs --by NAME: the trail says who decided"), usage);
    const QString format = parser.value(QStringLiteral("format"));
    if (action == QLatin1String("export")) {
        if (format != QLatin1String("csv") && format != QLatin1String("json"))
            return usageError(QStringLiteral("--format must be csv or json"), usage);
        if (!parser.isSet(QStringLiteral("output")))
            return usageError(QStringLiteral("--output PATH is required"), usage);
        if (parser.value(QStringLiteral("output")) == QLatin1String("-"))
            return usageError(QStringLiteral("--output names a file, not standard output (-): an export is written "
                                             "whole or not at all, a CSV's metadata beside it"),
                              usage);
        if (parser.isSet(QStringLiteral("derived")) && format != QLatin1String("csv"))
            return usageError(QStringLiteral("--derived goes with --format csv"), usage);
        if (parser.isSet(QStringLiteral("math")) && format != QLatin1String("csv"))
            return usageError(QStringLiteral("--math goes with --format csv"), usage);
    }
    const QString dbArgument = parser.value(QStringLiteral("db"));
    if (!storeArgumentExists(dbArgument)) return usageError(QStringLiteral("%1 does not exist").arg(dbArgument), usage);
    if (action == QLatin1String("upgrade")) return upgradeStore(dbArgument);

    try {
        // Only delete and verdict write; the others read, and work beside a recording.
        const auto opened = openStoreArgument(dbArgument, action == QLatin1String("delete") || decides
                                                              ? core::storage::Database::Access::ReadWrite
                                                              : core::storage::Database::Access::ReadOnly);
        SessionSource& store = *opened;
        const std::string db = store.location();
        if (action == QLatin1String("list")) {
            core::storage::SessionFilter filter;
            const auto value = [&](const char* option) {
                return parser.value(QString::fromLatin1(option)).toStdString();
            };
            if (parser.isSet(QStringLiteral("mode"))) {
                filter.mode = parseMode(parser.value(QStringLiteral("mode")));
                if (!filter.mode) return usageError(modeUsageError(), usage);
            }
            filter.subject = value("subject");
            filter.operatorName = value("operator");
            if (parser.isSet(QStringLiteral("verdict"))) {
                filter.verdict = verdictArgument(parser.value(QStringLiteral("verdict")));
                if (!filter.verdict)
                    return usageError(QStringLiteral("--verdict must be pass or defects-found"), usage);
            }
            if (parser.isSet(QStringLiteral("status"))) {
                filter.status = core::sessionStatusFromString(value("status"));
                if (!filter.status)
                    return usageError(QStringLiteral("--status must be complete, interrupted or recording"), usage);
            }
            filter.station = value("station");
            if (!filter.station.empty() && !core::storage::isCentralStoreAddress(dbArgument.toStdString()))
                return usageError(
                    QStringLiteral("--station goes with a central store: a station's file holds its own sessions"),
                    usage);
            filter.startedFrom = value("from");
            filter.startedBefore = value("before");
            filter.text = value("search");
            if (parser.isSet(QStringLiteral("limit")) && parser.isSet(QStringLiteral("all")))
                return usageError(QStringLiteral("--limit and --all: say one"), usage);
            filter.limit = kDefaultListed;
            if (parser.isSet(QStringLiteral("all"))) filter.limit = 0;
            if (parser.isSet(QStringLiteral("limit"))) {
                bool ok = false;
                const qlonglong limit = parser.value(QStringLiteral("limit")).toLongLong(&ok);
                if (!ok || limit < 1)
                    return usageError(QStringLiteral("--limit must be a whole number of sessions, 1 or more"), usage);
                filter.limit = static_cast<std::size_t>(limit);
            }
            if (parser.isSet(QStringLiteral("after"))) {
                bool ok = false;
                filter.after = parser.value(QStringLiteral("after")).toLongLong(&ok);
                if (!ok || !store.session(*filter.after))
                    return usageError(
                        QStringLiteral("--after names a listed session's id: there is no session %1 in %2")
                            .arg(quoted(parser.value(QStringLiteral("after"))), toQString(db)),
                        usage);
            }
            return list(store, filter, parser.isSet(QStringLiteral("json")));
        }
        const auto id = resolveSession(store, positional[1]);
        if (!id) {
            printError(positional[1] == QLatin1String("last")
                           ? QStringLiteral("%1 holds no sessions").arg(toQString(db))
                           : QStringLiteral("there is no session %1 in %2").arg(quoted(positional[1]), toQString(db)));
            return kExitUsage;
        }
        if (action == QLatin1String("show")) return show(store, *id, parser.isSet(QStringLiteral("json")));
        if (action == QLatin1String("export"))
            return exportSession(store, *id, format, parser.value(QStringLiteral("output")),
                                 parser.isSet(QStringLiteral("derived")), parser.values(QStringLiteral("math")));
        if (decides)
            return decideVerdict(store, *id, positional[2], parser.value(QStringLiteral("by")),
                                 parser.value(QStringLiteral("note")));
        store.deleteSession(*id);
        QTextStream(stdout) << "Deleted session " << *id << ".\n";
        return kExitOk;
    } catch (const StorageError& e) {
        return storageFailure(e);  // an unreachable server: 1, like every command; a damaged store: 2
    }
}

}  // namespace tactiscope::cli
