// The record subcommand: options, the devices with reconnection, and the
// live pipeline the GUI uses too (devices/session/LivePipeline), so a
// recording from here, of one device or several, manual or triggered,
// stores what the workstation would; what it tells is RecordOutput's.
#include "RecordCommand.h"

#include "CliSupport.h"
#include "PortLinks.h"
#include "ProbePort.h"
#include "RecordOutput.h"
#include "SignalOptions.h"
#include "WatchOptions.h"
#include "core/ModeCapability.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/SessionStore.h"
#include "devices/DriftWatch.h"
#include "devices/ReconnectingSource.h"
#include "devices/SteadyClock.h"
#include "devices/session/LivePipeline.h"
#include "devices/session/SessionOfDevices.h"

#include <QScopeGuard>
#include <QTextStream>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <thread>
#include <unistd.h>

namespace tactiscope::cli {
namespace {

constexpr int kDefaultBaud = 921600;
// How long past a set length, on the host's clock, a recording waits for
// its last samples (a board's lines come in bursts; a slow one's each
// second) before it stops without them.
constexpr double kLastSamplesWait_s = 2.0;

// Each port's device opened over its link and added to the pipeline under
// its name (the one given, else its model's, unlike every other); with
// several, each channel's role and unit given as DEVICE/CHANNEL. An exit
// code when one cannot be.
std::optional<int> addDevices(devices::session::LivePipeline& pipeline, const std::vector<ProbePortArgument>& ports,
                              const std::vector<PortLink>& links, const core::RoleAssignment& roles,
                              const core::UnitAssignment& units)
{
    const bool several = ports.size() > 1;
    // Units are the board's own, given before it is opened: with several,
    // by the name its port is given (NAME=PATH).
    std::map<std::string, core::UnitAssignment> unitsOf;  // by the port's name; "" for the only device
    for (const auto& [key, unit] : units) {
        if (!several) {
            unitsOf[""][key] = unit;
            continue;
        }
        const auto named = deviceAndChannel(key);
        if (!named) {
            printError(QStringLiteral("--units: with several devices, name each channel as DEVICE/CHANNEL, DEVICE "
                                      "being a name given to its port (--port DEVICE=PATH) ('%1')")
                           .arg(toQString(key)));
            return kExitUsage;
        }
        if (std::ranges::none_of(ports, [&](const ProbePortArgument& p) { return p.name == named->first; })) {
            printError(QStringLiteral("--units: no port is named %1 (name one with --port NAME=PATH)")
                           .arg(quoted(toQString(named->first))));
            return kExitUsage;
        }
        unitsOf[named->first][named->second] = unit;
    }
    std::map<std::string, core::RoleAssignment> rolesOf;  // by device name; "" for the only device
    for (const auto& [key, role] : roles) {
        if (!several) {
            rolesOf[""][key] = role;
            continue;
        }
        const auto named = deviceAndChannel(key);
        if (!named) {
            printError(QStringLiteral("--roles: with several devices, name each channel as DEVICE/CHANNEL (%1)")
                           .arg(quoted(toQString(key))));
            return kExitUsage;
        }
        rolesOf[named->first][named->second] = role;
    }
    for (std::size_t i = 0; i < ports.size(); ++i) {
        const auto& given = unitsOf[several ? ports[i].name : std::string()];
        if (!given.empty() && links[i].options.protocol != devices::WireProtocol::Text) {
            printError(QStringLiteral("--units is for a board that prints lines (--protocol %1text): a TSP/1 probe "
                                      "declares its channels' units")
                           .arg(several ? toQString(ports[i].name) + QLatin1Char('=') : QString()));
            return kExitUsage;
        }
    }
    std::vector<std::unique_ptr<devices::ReconnectingSource>> sources;
    for (std::size_t i = 0; i < ports.size(); ++i) {
        const ProbePortArgument& port = ports[i];
        // A board that states no rate is timed on its lines first, for
        // seconds, before anything is recorded: said, so that an unplug
        // meanwhile is understood (the recording has not begun; a device
        // lost during the recording is waited for).
        const bool timed = links[i].options.protocol == devices::WireProtocol::Text && !links[i].options.textRate_hz;
        if (timed)
            printError(QStringLiteral("%1: timing the board's lines (it states no rate; give --rate to skip this); "
                                      "the recording begins once they are timed")
                           .arg(toQString(port.path)));
        try {
            devices::PortSourceOptions portOptions = links[i].options;
            portOptions.textUnits = unitsOf[several ? port.name : std::string()];
            sources.push_back(openProbePort(port.path, links[i].baud, portOptions));
        } catch (const std::exception& e) {
            const QString before =
                timed
                    ? QStringLiteral(" (while its lines were timed, before the recording began: nothing was recorded)")
                    : QString();
            printError((several ? QStringLiteral("%1: %2").arg(toQString(port.path), toQString(e.what()))
                                : toQString(e.what())) +
                       before);
            return kExitFailure;
        }
    }
    // Names not given come from the devices, unlike the given ones and each other.
    std::vector<std::string> names;
    std::vector<std::string> taken;
    for (const ProbePortArgument& port : ports)
        if (!port.name.empty()) taken.push_back(port.name);
    for (std::size_t i = 0; i < ports.size(); ++i) {
        names.push_back(ports[i].name.empty() ? devices::session::partName(sources[i]->identity(), taken)
                                              : ports[i].name);
        taken.push_back(names.back());
    }
    for (const auto& [device, assignment] : rolesOf)
        if (several && std::ranges::find(names, device) == names.end()) {
            printError(QStringLiteral("--roles: there is no device %1").arg(quoted(toQString(device))));
            return kExitUsage;
        }
    for (std::size_t i = 0; i < sources.size(); ++i) {
        devices::session::LiveSessionOptions sessionOptions;
        sessionOptions.roles = rolesOf[several ? names[i] : std::string()];
        try {
            pipeline.add(std::move(sources[i]), std::move(sessionOptions), names[i]);
        } catch (const std::invalid_argument& e) {  // a role for a channel the device lacks
            printError(QStringLiteral("--roles: %1%2")
                           .arg(several ? toQString(names[i]) + QStringLiteral(": ") : "", toQString(e.what())));
            return kExitUsage;
        }
    }
    return std::nullopt;
}

// The only device's mode (the one asked for must run on it; without one,
// the device's own), profile and limits; an exit code when refused.
std::optional<int> setUpOneDevice(devices::session::LiveSession& session, std::optional<core::Mode> mode,
                                  std::optional<core::sensors::SensorProfile> profile, const WatchOptions& watch,
                                  const QCommandLineParser& parser)
{
    if (!mode) mode = session.declaredMode();
    // The profile first: its channel scales may be what lets the mode read the beams.
    if (profile) {
        if (const auto refusal = session.setProfile(*mode, std::move(*profile))) {
            printError(QStringLiteral("bad profile: %1").arg(QString::fromStdString(*refusal)));
            return kExitUsage;
        }
    }
    if (const auto refusal = session.setMode(*mode)) {
        // Roles or units missing: how to give them here.
        const auto unitless = core::channelsWithoutFittingUnit(*mode, session.channels());
        QString how;
        if (!unitless.empty())
            how = QStringLiteral(" Give %1 its unit with --units %1=UNIT, or have the board print it with its unit "
                                 "(%1[UNIT]:VALUE), "
                                 "or, for ADC counts, give its scale in the sensor profile's \"channels\"; or record "
                                 "without --mode (the general mode records plain numbers).")
                      .arg(toQString(unitless.front()));
        else if (session.refusalOf(*mode))
            how = QStringLiteral(" Give its channels roles with --roles %1, or record without --mode "
                                 "(the general mode records any channels).")
                      .arg(toQString(core::roleExample(*mode, session.channels())));
        printError(QStringLiteral("cannot record in this mode: %1%2").arg(QString::fromStdString(*refusal), how));
        return kExitUsage;
    }
    for (const auto& problem : session.takeProblems()) printError(QString::fromStdString(problem));
    // The filters and math channels before the limits, which may watch them.
    std::vector<std::string> channels;
    for (const auto& channel : session.channels()) channels.push_back(channel.name);
    core::signal::SignalSetup signal;
    if (const auto error = readSignalSetup(parser, channels, signal)) {
        printError(*error);
        return kExitUsage;
    }
    if (const auto refusal = session.setSignal(std::move(signal))) {
        printError(QStringLiteral("filters and math channels: %1").arg(QString::fromStdString(*refusal)));
        return kExitUsage;
    }
    if (const auto refusal = session.setLimits(watch.limits)) {
        printError(QStringLiteral("--limit: %1").arg(QString::fromStdString(*refusal)));
        return kExitUsage;
    }
    if (watch.stopOnCritical && std::ranges::none_of(session.limits(), [](const core::sensors::SensorLimit& l) {
            return l.limit.critical.has_value();
        })) {
        printError(QStringLiteral("--stop-on critical: no limit watched here has a critical level; give one with "
                                  "--limit QUANTITY>critical:C"));
        return kExitUsage;
    }
    return std::nullopt;
}

// Several devices' filters and math channels, each device's its own
// (SignalOptions.h: readSignalSetups); an exit code when refused.
std::optional<int> setUpSignals(devices::session::LivePipeline& pipeline, const QCommandLineParser& parser)
{
    std::vector<std::vector<std::string>> channels;
    for (std::size_t i = 0; i < pipeline.size(); ++i) {
        channels.emplace_back();
        for (const auto& channel : pipeline.device(i).channels()) channels.back().push_back(channel.name);
    }
    std::vector<core::signal::SignalSetup> setups;
    if (const auto error = readSignalSetups(parser, pipeline.names(), channels, setups)) {
        printError(*error);
        return kExitUsage;
    }
    for (std::size_t i = 0; i < pipeline.size(); ++i) {
        if (const auto refusal = pipeline.device(i).setSignal(std::move(setups[i]))) {
            printError(QStringLiteral("%1: filters and math channels: %2")
                           .arg(toQString(pipeline.name(i)), QString::fromStdString(*refusal)));
            return kExitUsage;
        }
    }
    return std::nullopt;
}

// The device's crystal against the host's (core/timing): what every time
// it stamped is off by, unmapped. Said once enough of its blocks were
// mapped for the drift to mean something (DriftWatch's span).
void tellDeviceClock(const std::optional<core::timing::ClockMapping>& clock, const devices::BlockSource& source)
{
    // Too few frames: its drift would be noise, so nothing is said.
    if (!clock || clock->span_s < devices::DriftWatch::kMinSpan_s ||
        clock->basis == core::timing::ClockUncertaintyBasis::TooFewFrames)
        return;
    if (source.textProtocol()) {
        // A text board has no clock to drift: the rate its lines were timed
        // at is what the mapping checks, as the rate they kept coming at.
        const double rate_hz = source.nominalSampleRate_hz();
        const double kept_hz = rate_hz / (1.0 + clock->drift);
        printError(QStringLiteral("the board's lines came at %1 ± %2 Hz over the last %3 s of them (by the host's "
                                  "clock; ± %4); the rate in use, %5 Hz, is %6 ppm off it")
                       .arg(kept_hz, 0, 'g', 8)
                       .arg(kept_hz * clock->drift_u, 0, 'g', 2)
                       .arg(clock->span_s, 0, 'f', 1)
                       .arg(QString::fromUtf8(core::timing::describe(clock->basis)))
                       .arg(rate_hz, 0, 'g', 8)
                       .arg(std::abs(rate_hz / kept_hz - 1.0) * 1e6, 0, 'f', 0));
        return;
    }
    printError(QStringLiteral("device clock: %1 ± %2 ppm %3 against the host's (mapped over %4 s of its blocks; ± %5)")
                   .arg(std::abs(clock->drift) * 1e6, 0, 'f', 1)
                   .arg(clock->drift_u * 1e6, 0, 'f', 1)
                   .arg(clock->drift >= 0.0 ? QStringLiteral("slow") : QStringLiteral("fast"))
                   .arg(clock->span_s, 0, 'f', 1)
                   .arg(QString::fromUtf8(core::timing::describe(clock->basis))));
}

}  // namespace

int runRecord(const QStringList& arguments)
{
    const QString name = QStringLiteral("record");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Record a TSP/1 probe, or a board printing text lines (--protocol text), on a serial port\n"
                       "into a session store, until --seconds or Ctrl-C, running the mode's analysis as the\n"
                       "workstation does: a panel scan stores its defects and verdict, a palpation its stiffness\n"
                       "readings, every session its profile and calibrations. An unplugged device is waited for\n"
                       "and the gap is marked in the recording."));
    parser.addOptions({
        {QStringLiteral("port"),
         QStringLiteral("Serial port or link to it (required). Given more than once, the devices are recorded into "
                        "one session, each as NAME (default: its model), their clocks mapped onto the host's."),
         QStringLiteral("[NAME=]PATH")},
        {QStringLiteral("protocol"),
         QStringLiteral("binary (TSP/1, default) or text. With several ports, NAME=text is that port's (this and "
                        "--baud and --rate are given once for every port, or once per port named: a rate given once "
                        "is asked of every TSP/1 probe too)."),
         QStringLiteral("[NAME=]binary|text")},
        {QStringLiteral("baud"),
         QStringLiteral("Baud rate (default %1, a TSP/1 probe's; a board's is its sketch's Serial.begin, such as "
                        "115200; a board with native USB takes any).")
             .arg(kDefaultBaud),
         QStringLiteral("[NAME=]N")},
        {QStringLiteral("rate"),
         QStringLiteral("Sample rate in Hz: text, the rate of the lines (else timed by the board's own clock or "
                        "their arrivals, checked against them when given); binary, asked of the device."),
         QStringLiteral("[NAME=]HZ")},
        {QStringLiteral("seconds"),
         QStringLiteral("Record this long: exactly S seconds of samples, on the device's clock (default: until "
                        "Ctrl-C; with --trigger, how long to watch)."),
         QStringLiteral("S")},
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
        unitsOption(QStringLiteral("a text board's channels, over its labels' units")),
    });
    parser.addOptions(watchOptions());
    parser.addOptions(signalOptions());
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument %1").arg(quoted(parser.positionalArguments().front())),
                          usage);
    if (!parser.isSet(QStringLiteral("port"))) return usageError(QStringLiteral("--port PATH is required"), usage);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);

    const auto ports = parseProbePorts(parser.values(QStringLiteral("port")));
    if (!ports)
        return usageError(QStringLiteral("--port: a device's NAME must be a word without '/' or '=', and "
                                         "each name given once"),
                          usage);
    const std::string db = parser.value(QStringLiteral("db")).toStdString();
    QString linkError;
    const auto links = parsePortLinks({parser.values(QStringLiteral("protocol")), parser.values(QStringLiteral("baud")),
                                       parser.values(QStringLiteral("rate"))},
                                      *ports, kDefaultBaud, linkError);
    if (!links) return usageError(linkError, usage);
    std::optional<double> seconds;
    if (parser.isSet(QStringLiteral("seconds"))) {
        QString error;
        seconds = numberInRange(parser, "seconds", core::kRecordingSecondsRange, 0.0, error);
        if (!seconds) return usageError(error, usage);
    }
    std::optional<core::Mode> mode;
    if (parser.isSet(QStringLiteral("mode"))) {
        mode = parseMode(parser.value(QStringLiteral("mode")));
        if (!mode) return usageError(modeUsageError(), usage);
    }
    QString rolesError;
    const auto roles = parseRolesOption(parser, rolesError);
    if (!roles) return usageError(rolesError, usage);
    QString unitsError;
    const auto units = parseUnitsOption(parser, unitsError);
    if (!units) return usageError(unitsError, usage);
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
        // A unit given for a channel the profile scales makes its values that
        // unit as printed: the profile's counts_per_unit no longer applies.
        const auto scales = core::sensors::profileScales(*profile);
        for (const auto& [channel, unit] : *units)
            if (const auto scaled = scales.find(channel); scaled != scales.end())
                printError(QStringLiteral("--units %1=%2: the profile scales %1's counts (%3 counts a %4); the unit "
                                          "given replaces that scale, so its values are read as %2 as printed")
                               .arg(toQString(channel), toQString(unit))
                               .arg(scaled->second.countsPerUnit)
                               .arg(toQString(scaled->second.unit)));
    }
    core::storage::SessionMetadata metadata;
    metadata.subject = parser.value(QStringLiteral("subject")).toStdString();
    metadata.operatorName = parser.value(QStringLiteral("operator")).toStdString();
    metadata.site = parser.value(QStringLiteral("site")).toStdString();

    // A store this command creates and then records nothing into (a
    // refused option, a device that cannot be reached) is not left behind.
    const bool storeExisted = std::filesystem::exists(db);
    bool recorded = false;
    const auto leaveNoEmptyStore = qScopeGuard([&] {
        if (storeExisted || recorded) return;
        std::error_code ignored;
        for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::filesystem::remove(db + suffix, ignored);
        std::filesystem::remove(core::storage::RecorderLock::lockPath(db), ignored);
    });
    // A store we may not write (not ours, newer, being recorded into) is bad
    // input: say so before touching the device.
    try {
        core::storage::SessionStore check(db);
        core::storage::RecorderLock::acquire(db);  // released at once; taken again by the recorder
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    if (ports->size() > 1 && (mode || profile || watch->trigger || !watch->limits.empty() || watch->stopOnCritical))
        return usageError(QStringLiteral("with several devices, each records in its own mode with its own "
                                         "limits; --mode, --profile, --trigger, --limit and --stop-on are for one "
                                         "device"),
                          usage);

    // Each device's first connection is made here, to know it before the
    // recording; its reconnecting source reopens it after an unplug.
    devices::session::LivePipeline pipeline(db);
    if (const auto exit = addDevices(pipeline, *ports, *links, *roles, *units)) return *exit;
    for (std::size_t i = 0; i < pipeline.size(); ++i) {
        const auto asked_hz = (*links)[i].options.requestRate_hz;
        const double rate_hz = pipeline.device(i).source().nominalSampleRate_hz();
        if (asked_hz && std::abs(rate_hz - *asked_hz) > 1e-6 * *asked_hz)
            printError(QStringLiteral("%1the device streams at %2 Hz, not the %3 Hz asked for; recording at %2 Hz")
                           .arg(pipeline.size() > 1 ? toQString(pipeline.name(i)) + QStringLiteral(": ") : QString())
                           .arg(rate_hz)
                           .arg(*asked_hz));
    }
    auto& first = pipeline.device(0);
    if (pipeline.size() == 1) {
        if (const auto exit = setUpOneDevice(first, mode, std::move(profile), *watch, parser)) return *exit;
    } else if (const auto exit = setUpSignals(pipeline, parser)) {
        return *exit;
    }

    // Recording from the first block (started before the devices stream),
    // or from each trigger. A recording of --seconds holds exactly that
    // long of samples (each device's), however late the last of them come.
    const std::optional<double> length_s = watch->trigger ? std::nullopt : seconds;
    const auto refused =
        watch->trigger ? pipeline.armTrigger(*watch->trigger, metadata) : pipeline.startRecording(metadata, length_s);
    if (refused) {
        printError(QStringLiteral("%1%2").arg(watch->trigger ? QStringLiteral("--trigger: ") : QString(),
                                              QString::fromStdString(*refused)));
        return kExitUsage;
    }
    recorded = true;  // a trigger's store stays, even should none fire: where its sessions were to go
    installStopSignals();
    pipeline.start();

    RecordOutput output(db, pipeline, watch->trigger, watch->stopOnCritical);
    const bool progress = ::isatty(STDERR_FILENO) != 0;
    // --seconds counts from where the recording begins: one device's from
    // its stream's start (a profile's setup between the connection and
    // here, tenths of a second, is recorded too, and was counted on top).
    // A recording of a set length ends when it has it, or, should its
    // samples stop coming, a little after its length on the host's clock.
    auto start = std::chrono::steady_clock::now();
    if (const auto streamStart_s = first.source().streamStart_host_s(); streamStart_s && pipeline.size() == 1)
        start = std::min(start, devices::steadyInstant(*streamStart_s));
    auto nextProgress = start + std::chrono::seconds(5);
    QTextStream err(stderr);
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const auto news = pipeline.poll();
        output.tell(news);
        if (news.triggerRefused) break;
        const auto now = std::chrono::steady_clock::now();
        const double elapsed_s = std::chrono::duration<double>(now - start).count();
        if (stopRequested() || output.criticalStop() || !pipeline.streaming() || pipeline.recordingComplete() ||
            (seconds && elapsed_s >= *seconds + (length_s ? kLastSamplesWait_s : 0.0)))
            break;
        if (watch->trigger) {
            // Every session the trigger was asked for is stored.
            if (pipeline.triggerStatus().state == core::trigger::TriggerState::Finished && !pipeline.isRecording())
                break;
        } else if (!pipeline.isRecording()) {
            break;  // it ended by itself: its disk, or every device's link
        }
        if (progress && now >= nextProgress) {
            nextProgress += std::chrono::seconds(5);
            err << "recording… " << std::llround(std::chrono::duration<double>(now - start).count()) << " s, "
                << first.stats().samples << " samples per channel\r" << Qt::flush;
        }
    }
    const auto clock = first.source().hostClock();
    const auto last = watch->trigger ? pipeline.disarmTrigger() : pipeline.stopRecording();
    output.tell(pipeline.poll());  // what came with the stop
    if (progress) err << '\n';
    if (last) output.report(*last);
    if (pipeline.size() == 1) tellDeviceClock(clock, first.source());
    if (const std::size_t missed = watch->trigger ? first.cutNotRecorded() : 0; missed > 0)
        printError(QStringLiteral("%1 more %2 the trigger cut could not be recorded before the stop: the store "
                                  "did not keep up with the trigger")
                       .arg(missed)
                       .arg(missed == 1 ? QStringLiteral("session") : QStringLiteral("sessions")));
    if (watch->trigger && watch->trigger->sessions && output.sessionsReported() < *watch->trigger->sessions)
        printError(QStringLiteral("%1 of %2 triggered sessions recorded before the stop")
                       .arg(output.sessionsReported())
                       .arg(*watch->trigger->sessions));
    if (pipeline.size() == 1 && first.stats().state == devices::AcquisitionState::Failed) {
        printError(QString::fromStdString(first.stats().error));
        return kExitFailure;
    }
    if (output.criticalStop()) {
        printError(*output.criticalStop() + QStringLiteral("; the recording was kept"));
        return kExitFailure;
    }
    return output.exitCode();
}

}  // namespace tactiscope::cli
