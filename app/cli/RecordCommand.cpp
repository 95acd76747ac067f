// The record subcommand: options, the device with reconnection, and the
// live-session controller the GUI uses too (devices/session/LiveSession),
// so a recording from here stores what the workstation would; the summary.
#include "RecordCommand.h"

#include "CliSupport.h"
#include "ProbePort.h"
#include "RecordDevices.h"
#include "WatchOptions.h"
#include "core/ModeCapability.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/SessionStore.h"
#include "devices/DriftWatch.h"
#include "devices/ReconnectingSource.h"
#include "devices/session/LiveSession.h"

#include <QLocale>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <unistd.h>

namespace tactiscope::cli {
namespace {

constexpr int kDefaultBaud = 921600;

}  // namespace

int runRecord(const QStringList& arguments)
{
    const QString name = QStringLiteral("record");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Record a probe on a serial port into a session store, until --seconds or Ctrl-C, running\n"
                       "the mode's analysis as the workstation does: a panel scan stores its defects and\n"
                       "verdict, a palpation its stiffness readings, every session its profile and calibrations.\n"
                       "An unplugged probe is waited for and the gap is marked in the recording."));
    parser.addOptions({
        {QStringLiteral("port"),
         QStringLiteral("Serial port or link to it (required). Given more than once, the devices are recorded into "
                        "one session, each as NAME (default: its model), their clocks mapped onto the host's."),
         QStringLiteral("[NAME=]PATH")},
        {QStringLiteral("protocol"), QStringLiteral("binary (TSP/1, default) or text."), QStringLiteral("binary|text")},
        {QStringLiteral("baud"), QStringLiteral("Baud rate (default %1).").arg(kDefaultBaud), QStringLiteral("N")},
        {QStringLiteral("rate"),
         QStringLiteral("Sample rate in Hz: text, the rate of the lines (else estimated); binary, asked of the "
                        "device."),
         QStringLiteral("HZ")},
        {QStringLiteral("seconds"), QStringLiteral("Record this long (default: until Ctrl-C)."), QStringLiteral("S")},
        {QStringLiteral("db"), QStringLiteral("Session store to record into (required; created if missing)."),
         QStringLiteral("FILE")},
        {QStringLiteral("subject"), QStringLiteral("Panel or phantom id."), QStringLiteral("ID")},
        {QStringLiteral("operator"), QStringLiteral("Who records."), QStringLiteral("NAME")},
        {QStringLiteral("site"), QStringLiteral("Where on the subject (palpation: the site of every reading)."),
         QStringLiteral("SITE")},
        {QStringLiteral("mode"), modeOptionText(QStringLiteral("(default: the device's own, from its channels).")),
         QStringLiteral("MODE")},
        {QStringLiteral("profile"),
         QStringLiteral("Sensor profile (JSON) for palpation or capacitive (default: the paper's, built in)."),
         QStringLiteral("FILE")},
        rolesOption(),
    });
    parser.addOptions(watchOptions());
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()), usage);
    if (!parser.isSet(QStringLiteral("port"))) return usageError(QStringLiteral("--port PATH is required"), usage);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);

    const auto ports = parseProbePorts(parser.values(QStringLiteral("port")));
    if (!ports)
        return usageError(QStringLiteral("--port: a device's NAME must be a word without '/' or '=', and "
                                         "each name given once"),
                          usage);
    const std::string port = ports->front().path;
    const std::string db = parser.value(QStringLiteral("db")).toStdString();
    devices::PortSourceOptions options;
    const auto protocol = parseWireProtocol(parser.value(QStringLiteral("protocol")));
    if (!protocol) return usageError(QStringLiteral("--protocol must be binary or text"), usage);
    options.protocol = *protocol;
    int baud = kDefaultBaud;
    if (parser.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        baud = parser.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || baud <= 0) return usageError(QStringLiteral("--baud must be a positive whole number"), usage);
    }
    if (parser.isSet(QStringLiteral("rate"))) {
        const auto rate = parseNumber(parser.value(QStringLiteral("rate")));
        if (!rate || *rate <= 0.0) return usageError(QStringLiteral("--rate must be a positive number of Hz"), usage);
        (options.protocol == devices::WireProtocol::Text ? options.textRate_hz : options.requestRate_hz) = rate;
    }
    std::optional<double> seconds;
    if (parser.isSet(QStringLiteral("seconds"))) {
        seconds = parseNumber(parser.value(QStringLiteral("seconds")));
        if (!seconds || *seconds <= 0.0)
            return usageError(QStringLiteral("--seconds must be a positive number"), usage);
    }
    std::optional<core::Mode> mode;
    if (parser.isSet(QStringLiteral("mode"))) {
        mode = parseMode(parser.value(QStringLiteral("mode")));
        if (!mode) return usageError(modeUsageError(), usage);
    }
    QString rolesError;
    const auto roles = parseRolesOption(parser, rolesError);
    if (!roles) return usageError(rolesError, usage);
    QString watchError;
    const auto watch = parseWatchOptions(parser, watchError);
    if (!watch) return usageError(watchError, usage);
    std::optional<core::sensors::SensorProfile> profile;
    if (parser.isSet(QStringLiteral("profile"))) {
        try {
            profile = core::sensors::loadSensorProfile(parser.value(QStringLiteral("profile")).toStdString());
        } catch (const core::sensors::ProfileError& e) {
            printError(QStringLiteral("bad profile: %1").arg(QString::fromStdString(e.what())));
            return kExitUsage;
        }
    }
    core::storage::SessionMetadata metadata;
    metadata.subject = parser.value(QStringLiteral("subject")).toStdString();
    metadata.operatorName = parser.value(QStringLiteral("operator")).toStdString();
    metadata.site = parser.value(QStringLiteral("site")).toStdString();

    // A store we may not write (not ours, newer, being recorded into) is bad
    // input: say so before touching the device.
    try {
        core::storage::SessionStore check(db);
        core::storage::RecorderLock::acquire(db);  // released at once; taken again by the recorder
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    if (ports->size() > 1) {
        if (mode || profile || watch->trigger || !watch->limits.empty() || watch->stopOnCritical)
            return usageError(QStringLiteral("with several devices, each records in its own mode with its own "
                                             "limits; --mode, --profile, --trigger, --limit and --stop-on are for "
                                             "one device"),
                              usage);
        return recordDevices({*ports, db, options, baud, seconds, metadata, *roles});
    }

    // The first connection is made here, to know the device before the
    // recording; the reconnecting source takes it over and reopens it after
    // an unplug.
    std::unique_ptr<devices::ReconnectingSource> source;
    try {
        source = openProbePort(port, baud, options);
    } catch (const std::exception& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    const double rate_hz = source->nominalSampleRate_hz();
    if (options.requestRate_hz && std::abs(rate_hz - *options.requestRate_hz) > 1e-6 * *options.requestRate_hz)
        printError(QStringLiteral("the device streams at %1 Hz, not the %2 Hz asked for; recording at %1 Hz")
                       .arg(rate_hz)
                       .arg(*options.requestRate_hz));
    const auto channels = source->channels();
    const auto* device = source.get();

    devices::session::LiveSessionOptions sessionOptions;
    sessionOptions.storePath = db;
    sessionOptions.roles = *roles;
    std::unique_ptr<devices::session::LiveSession> live;
    try {
        live = std::make_unique<devices::session::LiveSession>(std::move(source), sessionOptions);
    } catch (const std::invalid_argument& e) {  // a role for a channel the device lacks
        printError(QStringLiteral("--roles: %1").arg(QString::fromStdString(e.what())));
        return kExitUsage;
    }
    auto& session = *live;
    // The mode asked for must run on the device; without one, the device's
    // own (general for a device that declares none its channels feed).
    if (!mode) mode = session.declaredMode();
    if (const auto refusal = session.setMode(*mode)) {
        // Roles missing: how to give them here.
        const QString how = session.refusalOf(*mode)
                                ? QStringLiteral(" Give its channels roles with --roles %1, or record without --mode "
                                                 "(the general mode records any channels).")
                                      .arg(toQString(core::roleExample(*mode, session.channels())))
                                : QString();
        printError(QStringLiteral("cannot record in this mode: %1%2").arg(QString::fromStdString(*refusal), how));
        return kExitUsage;
    }
    if (profile) {
        if (const auto refusal = session.setProfile(*mode, std::move(*profile))) {
            printError(QStringLiteral("bad profile: %1").arg(QString::fromStdString(*refusal)));
            return kExitUsage;
        }
    }
    for (const auto& problem : session.takeProblems()) printError(QString::fromStdString(problem));
    session.setSite(metadata.site);
    if (const auto refusal = session.setLimits(watch->limits)) {
        printError(QStringLiteral("--limit: %1").arg(QString::fromStdString(*refusal)));
        return kExitUsage;
    }
    if (watch->stopOnCritical && std::ranges::none_of(session.limits(), [](const core::sensors::SensorLimit& l) {
            return l.limit.critical.has_value();
        })) {
        printError(QStringLiteral("--stop-on critical: no limit watched here has a critical level; give one with "
                                  "--limit QUANTITY>critical:C"));
        return kExitUsage;
    }
    // Recording from the first block (attached before the device streams),
    // or from each trigger.
    const auto refused =
        watch->trigger ? session.armTrigger(*watch->trigger, metadata) : session.startRecording(metadata);
    if (refused) {
        printError(QStringLiteral("%1%2").arg(watch->trigger ? QStringLiteral("--trigger: ") : QString(),
                                              QString::fromStdString(*refused)));
        return kExitUsage;
    }
    installStopSignals();
    session.start();

    const bool progress = ::isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    auto nextProgress = start + std::chrono::seconds(5);
    QTextStream err(stderr);
    const auto at = [](double time_s) { return QLocale::c().toString(time_s, 'f', 1); };
    // What the link noticed is stored as an alarm and told here, as it comes.
    const auto tellNotices = [&] {
        for (const auto& notice : session.takeLinkNotices())
            printError(QStringLiteral("at %1 s: %2").arg(at(notice.time_s), QString::fromStdString(notice.text)));
    };
    // Limit alarms likewise; a critical one ends the recording when asked.
    std::optional<QString> criticalStop;
    const auto tellAlarms = [&] {
        for (const auto& alarm : session.takeAlarms()) {
            const QString severity = QString::fromLatin1(core::trigger::toString(alarm.change.severity));
            const QString text = QString::fromStdString(alarm.text());
            printError(alarm.change.raised ? QStringLiteral("at %1 s: %2: %3").arg(at(alarm.time_s), severity, text)
                                           : QStringLiteral("at %1 s: cleared: %2").arg(at(alarm.time_s), text));
            if (watch->stopOnCritical && alarm.change.raised && !criticalStop &&
                alarm.change.severity == core::trigger::LimitSeverity::Critical)
                criticalStop = QStringLiteral("stopped on a critical alarm at %1 s: %2").arg(at(alarm.time_s), text);
        }
    };
    // The trigger's state as it changes.
    std::optional<devices::session::TriggerStatus> toldState;
    const auto tellTrigger = [&] {
        if (!watch->trigger) return;
        const auto status = session.triggerStatus();
        if (toldState && toldState->state == status.state && toldState->sessionsCut == status.sessionsCut) return;
        toldState = status;
        using core::trigger::TriggerState;
        switch (status.state) {
        case TriggerState::Waiting:
            printError(QStringLiteral("trigger waiting: %1 must first not hold")
                           .arg(toQString(watch->trigger->condition.text())));
            break;
        case TriggerState::Armed:
            printError(QStringLiteral("trigger armed: %1").arg(toQString(watch->trigger->condition.text())));
            break;
        case TriggerState::Triggered:
            printError(QStringLiteral("triggered: session %1%2")
                           .arg(status.sessionsCut + 1)
                           .arg(watch->trigger->sessions ? QStringLiteral(" of %1").arg(*watch->trigger->sessions)
                                                         : QString()));
            break;
        case TriggerState::Finished:
            break;
        }
    };

    // One line per session stored (the contract line), and whether it ended well.
    int exit = kExitOk;
    unsigned stored = 0;
    const auto report = [&](const devices::session::RecordingSummary& summary,
                            const devices::AcquisitionStats& acquired) {
        ++stored;
        const auto& written = summary.stats;
        // The samples lost are what the store marks as lost (its gaps), so
        // the line and the store agree to the sample; what was counted while
        // recording if the store cannot be read back.
        std::uint64_t lost = acquired.samplesLost + written.samplesDropped + summary.samplesLostAtEnd;
        try {
            core::storage::SessionStore readBack(db, core::storage::Database::Access::ReadOnly);
            lost = 0;
            for (const auto& gap : readBack.gaps(summary.session)) lost += gap.count;
        } catch (const core::storage::StorageError&) {
        }
        QTextStream(stdout) << "Recorded session " << summary.session << ": " << written.samplesWritten
                            << " samples per channel, " << lost << " lost, " << device->decoderCounters().crcErrors
                            << " CRC errors (" << channels.size() << " channels at " << QLocale::c().toString(rate_hz)
                            << " Hz, into " << QString::fromStdString(db) << "); "
                            << toQString(core::toString(session.recordingMetadata().mode)) << ": "
                            << QString::fromStdString(summary.analysis) << Qt::endl;
        if (!written.error.empty()) {
            printError(QString::fromStdString(written.error));
            exit = kExitFailure;
        } else if (summary.lostAt_s) {
            printError(QStringLiteral("the probe was lost at %1 s and did not come back; %2 samples kept")
                           .arg(at(*summary.lostAt_s))
                           .arg(written.samplesWritten));
            exit = kExitFailure;
        }
    };
    const auto reportTriggered = [&] {
        for (const auto& summary : session.takeTriggeredSummaries()) report(summary, {});
    };

    std::optional<devices::session::RecordingSummary> summary;
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        summary = session.poll();
        tellNotices();
        tellAlarms();
        tellTrigger();
        reportTriggered();
        if (summary) break;  // the disk stopped it
        if (const auto refusal = session.takeTriggerRefusal()) {
            printError(QStringLiteral("the trigger could not start a recording: %1; the trigger was disarmed")
                           .arg(QString::fromStdString(*refusal)));
            exit = kExitFailure;
            break;
        }
        const auto now = std::chrono::steady_clock::now();
        const auto state = session.stats().state;
        if (stopRequested() || criticalStop || state == devices::AcquisitionState::Finished ||
            state == devices::AcquisitionState::Failed ||
            (seconds && std::chrono::duration<double>(now - start).count() >= *seconds))
            break;
        // Every session the trigger was asked for is stored.
        if (watch->trigger && session.triggerStatus().state == core::trigger::TriggerState::Finished &&
            !session.isRecording())
            break;
        if (progress && now >= nextProgress) {
            nextProgress += std::chrono::seconds(5);
            err << "recording… " << std::llround(std::chrono::duration<double>(now - start).count()) << " s, "
                << session.stats().samples << " samples per channel\r" << Qt::flush;
        }
    }
    const auto acquired = session.stats();
    const auto clock = session.source().hostClock();
    if (!summary) summary = watch->trigger ? session.disarmTrigger() : session.stopRecording();
    tellNotices();
    tellAlarms();
    if (progress) err << '\n';
    reportTriggered();
    if (summary) report(*summary, acquired);
    // The device's crystal against the host's (core/timing): what every
    // time it stamped is off by, unmapped. Said once enough of its blocks
    // were mapped for the drift to mean something (DriftWatch's span).
    if (clock && clock->span_s >= devices::DriftWatch::kMinSpan_s)
        printError(QStringLiteral("device clock: %1 ppm %2 against the host's (mapped over %3 s of its blocks; ± %4)")
                       .arg(clock->basis == core::timing::ClockUncertaintyBasis::TooFewFrames
                                ? QString::number(std::abs(clock->drift) * 1e6, 'f', 1)
                                : QStringLiteral("%1 ± %2")
                                      .arg(std::abs(clock->drift) * 1e6, 0, 'f', 1)
                                      .arg(clock->drift_u * 1e6, 0, 'f', 1))
                       .arg(clock->drift >= 0.0 ? QStringLiteral("slow") : QStringLiteral("fast"))
                       .arg(clock->span_s, 0, 'f', 1)
                       .arg(QString::fromUtf8(core::timing::describe(clock->basis))));
    if (watch->trigger && watch->trigger->sessions && stored < *watch->trigger->sessions)
        printError(QStringLiteral("%1 of %2 triggered sessions recorded before the stop")
                       .arg(stored)
                       .arg(*watch->trigger->sessions));
    if (acquired.state == devices::AcquisitionState::Failed) {
        printError(QString::fromStdString(acquired.error));
        return kExitFailure;
    }
    if (criticalStop) {
        printError(*criticalStop + QStringLiteral("; the recording was kept"));
        return kExitFailure;
    }
    return exit;
}

}  // namespace tactiscope::cli
