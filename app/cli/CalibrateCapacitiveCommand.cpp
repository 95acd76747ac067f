// The calibrate-capacitive subcommand: a calibration recording (raw
// capacitance with its loads, or rows of force and capacitance), or a
// stored sweep against a reference force, to C0, the sensitivity, the
// drift, the hysteresis and the detection limit.
#include "CalibrateCapacitiveCommand.h"

#include "CapacitiveCalibrationOutput.h"
#include "CliSupport.h"
#include "RecordingImport.h"
#include "SessionArgument.h"
#include "core/UnitScale.h"
#include "core/calibration/CapacitiveSweep.h"
#include "core/derived/ReferencedSweep.h"
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::cli {
namespace {

using namespace core;

// The rows form: force_n,capacitance_pf (and a time column when there is
// one), either step means or every sample with its load.
std::optional<QString> readRows(const QString& path, calibration::CapacitiveRecording& recording)
{
    const std::vector<std::string> header = io::CsvReader(path.toStdString()).header();
    std::vector<std::string> wanted{"force_n", "capacitance_pf"};
    for (const char* time : {"t", "t [s]", "time_s"})
        if (std::ranges::find(header, std::string(time)) != header.end()) {
            wanted.emplace_back(time);
            break;
        }
    const io::CsvColumns csv = io::readCsvColumns(path.toStdString(), wanted);
    std::size_t leadingZeros = 0;
    while (leadingZeros < csv.rowCount() && csv.columns[0][leadingZeros] == 0.0) ++leadingZeros;
    for (std::size_t i = 0; i < csv.rowCount(); ++i) {
        if (csv.columns[0][i] < 0.0)
            return QStringLiteral("'%1' line %2: force must not be negative").arg(path).arg(csv.lines[i]);
        recording.load_n.push_back(csv.columns[0][i]);
        recording.capacitance_f.push_back(csv.columns[1][i] * 1e-12);
        if (wanted.size() == 3) recording.t_s.push_back(csv.columns[2][i]);
    }
    if (leadingZeros < 2)
        return QStringLiteral("'%1': at least two rows with force 0 are needed for the baseline").arg(path);
    return std::nullopt;
}

// A raw recording through the importer: its capacitance channel (in the
// header's unit, or `unit` for a column without one) and its load column.
std::optional<QString> readRaw(const QString& path, const QString& unit, calibration::CapacitiveRecording& recording)
{
    ImportedRecording imported(path.toStdString(), Mode::Capacitive);
    const auto& channels = imported.result().channels;
    std::optional<std::size_t> capacitance, load;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        if (!capacitance && channels[c].kind == ChannelKind::Capacitance) capacitance = c;
        if (!capacitance && !unit.isEmpty() && channels[c].unit.empty() && channels[c].name == "capacitance")
            capacitance = c;
        if (!load && channels[c].kind == ChannelKind::Force) load = c;
    }
    if (!capacitance)
        return QStringLiteral("'%1' has no capacitance column: name its unit in the header ('capacitance [pF]') "
                              "or give --unit")
            .arg(path);
    const std::string capacitanceUnit =
        channels[*capacitance].unit.empty() ? unit.toStdString() : channels[*capacitance].unit;
    const auto scale = faradsPer(capacitanceUnit);
    if (!scale) return QStringLiteral("capacitance in %1: use F, nF, pF or fF").arg(quoted(toQString(capacitanceUnit)));
    const double loadScale = load ? newtonsPer(channels[*load].unit).value_or(1.0) : 1.0;
    auto& store = imported.store();
    const auto summary = store.session(imported.session());
    const std::uint64_t n = summary->sampleCount;
    const auto c = store.readChannel(imported.session(), *capacitance, 0, n);
    const auto l = load ? store.readChannel(imported.session(), *load, 0, n) : std::vector<double>{};
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (std::isnan(c[i]) || (load && std::isnan(l[i]))) continue;  // a row the file lacks
        recording.t_s.push_back(static_cast<double>(i) / summary->sampleRate_hz);
        recording.capacitance_f.push_back(c[i] * *scale);
        if (load) recording.load_n.push_back(l[i] * loadScale);
    }
    return std::nullopt;
}

// "0,10,20" in mgf → newtons; none when a value is not a number ≥ 0.
std::optional<std::vector<double>> parseLoads(const QString& text)
{
    std::vector<double> loads;
    for (const QString& item : text.split(QLatin1Char(','))) {
        const auto value = parseNumber(item.trimmed());
        if (!value || *value < 0.0) return std::nullopt;
        loads.push_back(*value * calibration::kMilligramForce_n);
    }
    return loads;
}

// A channel named on the command line, or the one playing `role`.
std::optional<derived::SessionChannel> channelFor(storage::SessionSource& store, std::int64_t session,
                                                  const QString& label, ChannelRole role)
{
    return label.isEmpty() ? derived::channelPlaying(store, session, role)
                           : derived::channelNamed(store, session, label.toStdString());
}

// A stored sweep of the beam against a reference force, each from any
// device of the session.
int calibrateStoredSweep(const QCommandLineParser& parser, const QString& usage, std::optional<double> area_m2,
                         std::optional<double> wander_f_per_sqrt_s)
{
    calibration::SweepSteps sweep;
    calibration::CapacitiveCalibrationResult result;
    SweepReport report;
    try {
        const auto opened = openStoreArgument(parser.value(QStringLiteral("db")), storage::Database::Access::ReadOnly);
        storage::SessionSource& store = *opened;
        const QString text = parser.value(QStringLiteral("session"));
        const auto id = resolveSession(store, text);
        if (!id) return usageError(QStringLiteral("no session %1 in the store").arg(quoted(text)), usage);
        const QString capacitanceLabel = parser.value(QStringLiteral("capacitance"));
        const QString referenceLabel = parser.value(QStringLiteral("reference"));
        const auto capacitance = channelFor(store, *id, capacitanceLabel, ChannelRole::Capacitance);
        if (!capacitance)
            return usageError(capacitanceLabel.isEmpty()
                                  ? QStringLiteral("session %1 has no capacitance channel").arg(*id)
                                  : QStringLiteral("session %1 has no channel %2 (name it DEVICE/CHANNEL)")
                                        .arg(*id)
                                        .arg(quoted(capacitanceLabel)),
                              usage);
        const auto reference = channelFor(store, *id, referenceLabel, ChannelRole::ReferenceForce);
        if (!reference)
            return usageError(referenceLabel.isEmpty()
                                  ? QStringLiteral("session %1 has no reference force: no channel plays "
                                                   "reference-force and none is a force; name one with --reference "
                                                   "DEVICE/CHANNEL")
                                        .arg(*id)
                                  : QStringLiteral("session %1 has no channel %2 (name it DEVICE/CHANNEL)")
                                        .arg(*id)
                                        .arg(quoted(referenceLabel)),
                              usage);
        const derived::ReferencedSweep paired = derived::referencedSweep(store, *capacitance, *reference);
        sweep =
            calibration::stepsFromSweep(paired.recording, {.stability = calibration::capacitiveStabilityDefaults()});
        sweep.steps.input.contactArea_m2 = area_m2;
        sweep.steps.input.baselineWander_f_per_sqrt_s = wander_f_per_sqrt_s;
        result = calibration::calibrateCapacitive(sweep.steps.input, capacitance->label(), "");
        if (!paired.clockUncertainty_s)
            result.cautions.push_back("the two devices' clocks were mapped without a stated uncertainty (too few "
                                      "frames): how well each capacitance sample meets its force is not known");
        report = {reference->label(),
                  capacitance->label(),
                  sweep.referenceZero_n,
                  sweep.span_n,
                  sweep.turns,
                  sweep.lag_s,
                  paired.recording.t_s.size(),
                  paired.outsideReference,
                  paired.clockUncertainty_s,
                  paired.steepest_n_per_s};
    } catch (const storage::StorageError& e) {
        return storageFailure(e);
    } catch (const std::invalid_argument& e) {  // units, no sweep, an unsettled start
        printError(QStringLiteral("session %1: %2").arg(parser.value(QStringLiteral("session")), toQString(e.what())));
        return kExitUsage;
    }
    if (!result.forceFit || !(result.forceFit->slope > 0.0)) {
        printError(QStringLiteral("the capacitance does not rise with the reference force; check the channels"));
        return kExitUsage;
    }
    if (parser.isSet(QStringLiteral("json")))
        writeCapacitiveJson(result, sweep.steps, true, &report);
    else
        writeCapacitiveText(result, sweep.steps, true, &report);
    return kExitOk;
}

}  // namespace

int runCalibrateCapacitive(const QStringList& arguments)
{
    const QString name = QStringLiteral("calibrate-capacitive");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "C0, sensitivity, drift, hysteresis and detection limit of a capacitive beam (seed 002).\n"
        "RECORDING.csv is a raw recording — a time column, the capacitance ('capacitance [F]' or [pF]) and the "
        "load placed ('load [N]', as the simulator writes it) — or, without a load column, the loads in order "
        "with --loads-mgf; or rows force_n,capacitance_pf (step means or every sample). The first baseline gives "
        "C0 and its noise, the last the drift, removed before the hysteresis.\n"
        "Or, with --db and --session, a recorded sweep against a reference force (a load cell on this or another "
        "device of the session): the beam's samples are paired with the force at their instants on the session's "
        "clock, and gathered in force bins, loading and unloading apart."));
    parser.addPositionalArgument(QStringLiteral("RECORDING.csv"),
                                 QStringLiteral("The calibration recording (without --session)."));
    parser.addOptions({
        {QStringLiteral("loads-mgf"),
         QStringLiteral("The loads placed, in order, in mgf, the unloaded baseline first (0,10,20,…,0)."),
         QStringLiteral("LIST")},
        {QStringLiteral("unit"), QStringLiteral("Unit of a capacitance column without one: F or pF."),
         QStringLiteral("UNIT")},
        {QStringLiteral("contact-area-mm2"), QStringLiteral("Contact area for the pressure sensitivity (e.g. 9)."),
         QStringLiteral("A")},
        {QStringLiteral("baseline-wander"),
         QStringLiteral("The beam's baseline stability, a random walk in pF/√s (e.g. 0.0002): its wander between "
                        "the two baselines then enters the sensitivity's ±."),
         QStringLiteral("S")},
        {QStringLiteral("json"), QStringLiteral("Print one JSON object.")},
        {QStringLiteral("db"), QStringLiteral("The session store of a sweep (with --session)."),
         QStringLiteral("FILE|CONNINFO")},
        {QStringLiteral("session"), QStringLiteral("The sweep's session: its id, its uuid, or 'last'."),
         QStringLiteral("ID|UUID|last")},
        {QStringLiteral("reference"),
         QStringLiteral("The reference force channel, DEVICE/CHANNEL (default: the one playing reference-force, else "
                        "the first force channel)."),
         QStringLiteral("LABEL")},
        {QStringLiteral("capacitance"),
         QStringLiteral("The beam's capacitance channel, DEVICE/CHANNEL (default: the first capacitance)."),
         QStringLiteral("LABEL")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    const bool stored = parser.isSet(QStringLiteral("session"));
    if (stored != parser.isSet(QStringLiteral("db")))
        return usageError(QStringLiteral("a stored sweep needs both --db and --session"), usage);
    if (stored ? !parser.positionalArguments().isEmpty() : parser.positionalArguments().size() != 1)
        return usageError(stored ? QStringLiteral("give either RECORDING.csv or --db and --session")
                                 : QStringLiteral("calibrate-capacitive needs RECORDING.csv"),
                          usage);
    for (const char* option : {"reference", "capacitance"})
        if (!stored && parser.isSet(QLatin1String(option)))
            return usageError(QStringLiteral("--%1 names a channel of a stored sweep (with --session)").arg(option),
                              usage);
    if (stored && (parser.isSet(QStringLiteral("loads-mgf")) || parser.isSet(QStringLiteral("unit"))))
        return usageError(QStringLiteral("--loads-mgf and --unit are for a recording file; a stored sweep's "
                                         "reference gives its loads and its channels their units"),
                          usage);
    std::optional<double> area_m2;
    if (parser.isSet(QStringLiteral("contact-area-mm2"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("contact-area-mm2")));
        if (!value || *value <= 0.0)
            return usageError(QStringLiteral("--contact-area-mm2 must be a positive number"), usage);
        area_m2 = *value * 1e-6;
    }
    std::optional<double> wander_f_per_sqrt_s;
    if (parser.isSet(QStringLiteral("baseline-wander"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("baseline-wander")));
        if (!value || *value < 0.0)
            return usageError(QStringLiteral("--baseline-wander must be a number of pF/√s, 0 or more"), usage);
        wander_f_per_sqrt_s = *value * 1e-12;
    }
    if (stored) return calibrateStoredSweep(parser, usage, area_m2, wander_f_per_sqrt_s);
    std::optional<std::vector<double>> loads;
    if (parser.isSet(QStringLiteral("loads-mgf"))) {
        loads = parseLoads(parser.value(QStringLiteral("loads-mgf")));
        if (!loads || loads->size() < 3)
            return usageError(QStringLiteral("--loads-mgf must list numbers ≥ 0, the baseline and two loads at least"),
                              usage);
    }
    const QString unit = parser.value(QStringLiteral("unit"));
    if (!unit.isEmpty() && !faradsPer(unit.toStdString()))
        return usageError(QStringLiteral("--unit must be F, nF, pF or fF"), usage);

    const QString path = parser.positionalArguments().front();
    calibration::CapacitiveRecording recording;
    calibration::CapacitiveSteps steps;
    calibration::CapacitiveCalibrationResult result;
    try {
        const std::vector<std::string> header = io::CsvReader(path.toStdString()).header();
        const bool rows = std::ranges::find(header, std::string("force_n")) != header.end();
        if (const auto problem = rows ? readRows(path, recording) : readRaw(path, unit, recording)) {
            printError(*problem);
            return kExitUsage;
        }
        const auto stability = calibration::capacitiveStabilityDefaults();
        if (!recording.load_n.empty()) {
            steps = calibration::stepsFromLoads(recording, stability);
        } else if (loads) {
            steps = calibration::stepsFromPlateaus(recording, *loads, stability);
        } else {
            printError(QStringLiteral("'%1' has no load column: give the loads placed, in order, with --loads-mgf "
                                      "0,10,20,…")
                           .arg(path));
            return kExitUsage;
        }
        steps.input.contactArea_m2 = area_m2;
        steps.input.baselineWander_f_per_sqrt_s = wander_f_per_sqrt_s;
        result = calibration::calibrateCapacitive(steps.input, path.toStdString(), "");
    } catch (const std::exception&) {  // the file, its steps
        return exitForReadError(path);
    }
    if (!result.forceFit || !(result.forceFit->slope > 0.0)) {
        printError(QStringLiteral("'%1': capacitance does not rise with force; check the columns").arg(path));
        return kExitUsage;
    }
    const bool timed = !recording.t_s.empty();
    if (parser.isSet(QStringLiteral("json")))
        writeCapacitiveJson(result, steps, timed, nullptr);
    else
        writeCapacitiveText(result, steps, timed, nullptr);
    return kExitOk;
}

}  // namespace tactiscope::cli
