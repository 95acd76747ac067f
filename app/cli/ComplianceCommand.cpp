// The compliance subcommand: a recording (raw counts or strain, or forces
// already computed) to the object stiffness, press by press or the paper's
// step way.
#include "ComplianceCommand.h"

#include "CliSupport.h"
#include "ComplianceOutput.h"
#include "RecordingImport.h"
#include "core/ModeCapability.h"
#include "core/compliance/LivePalpation.h"
#include "core/compliance/ReferenceTissues.h"
#include "core/compliance/StepProcedure.h"
#include "core/derived/PalpationReanalysis.h"
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"
#include "core/sensors/SensorProfile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace tactiscope::cli {
namespace {

using namespace core;

constexpr const char* kForceColumns[] = {"displacement_m", "force_high_n", "force_low_n"};

// A file of calibration records (one toJson() object or an array of them)
// with at least one gauge factor of the probe's beams. Throws
// std::runtime_error naming what is wrong.
std::vector<calibration::CalibrationRecord> loadGaugeFactors(const std::string& path,
                                                             const sensors::CompliancePairProfile& probe)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open '" + path + "'");
    const auto json = nlohmann::json::parse(in, nullptr, false);
    if (json.is_discarded()) throw std::runtime_error("'" + path + "' is not JSON");
    const auto records = calibration::recordsFromJsonArray(json.is_array() ? json.dump() : "[" + json.dump() + "]");
    const std::string stiff = calibration::beamSensorName(probe.name, true);
    const std::string soft = calibration::beamSensorName(probe.name, false);
    const bool applies = std::ranges::any_of(records, [&](const calibration::CalibrationRecord& r) {
        return r.kind == calibration::kGaugeFactorKind && (r.sensorName == stiff || r.sensorName == soft);
    });
    if (!applies)
        throw std::runtime_error("'" + path + "' has no gauge_factor record for '" + stiff + "' or '" + soft + "'");
    return records;
}

// A beam channel must say what it holds: counts, strain or force.
std::optional<QString> unitlessBeam(const std::vector<ChannelDescriptor>& channels)
{
    if (modeChannels(Mode::Palpation, channels)) return std::nullopt;
    // A plain-number column plays no beam: its unit is what is missing.
    for (const auto& c : channels) {
        if (c.kind == ChannelKind::Other && c.unit.empty())
            return QStringLiteral("the beam column '%1' has no unit: name it in the header ('%1 [count]', "
                                  "'%1 [strain]' or '%1 [N]')")
                .arg(toQString(c.name));
    }
    return toQString(*modeRefusal(Mode::Palpation, channels));
}

struct Options {
    double contact_n = 0.01;
    bool steps = false;
    compliance::StepSettings stepSettings;
    std::optional<QString> calibrationPath;
};

// The old form: forces in N, zeroed already; all contact rows are one press.
int readForceColumns(const QString& path, const sensors::CompliancePair& pair, const Options& options,
                     ComplianceOutput& output)
{
    io::CsvColumns csv;
    try {
        csv = io::readCsvColumns(path.toStdString(), {kForceColumns[0], kForceColumns[1], kForceColumns[2]});
    } catch (const io::CsvError& e) {
        printError(toQString(e.what()));
        return kExitUsage;
    }
    output.source = QStringLiteral("forces as given (zeroed by whoever wrote them)");
    if (options.steps) {
        auto settings = options.stepSettings;
        settings.contactThreshold_n = options.contact_n;
        output.steps = compliance::readSteps(pair, csv.columns[0], csv.columns[1], csv.columns[2], settings);
        return kExitOk;
    }
    std::vector<double> displacement, high, low;
    for (std::size_t i = 0; i < csv.rowCount(); ++i) {
        if (csv.columns[1][i] > options.contact_n && csv.columns[2][i] > options.contact_n) {
            displacement.push_back(csv.columns[0][i]);
            high.push_back(csv.columns[1][i]);
            low.push_back(csv.columns[2][i]);
        }
    }
    if (displacement.empty()) {
        printError(QStringLiteral("%1: no row has both forces above the contact threshold of %2 N")
                       .arg(path)
                       .arg(options.contact_n));
        return kExitUsage;
    }
    output.rows = ComplianceOutput::Rows{csv.rowCount() - displacement.size()};
    output.presses.push_back(compliance::readPress(pair, displacement, high, low));
    return kExitOk;
}

// A raw recording: through the importer, the profile's chain and the beam
// model, read as the live view reads it.
int readRecording(const QString& path, const sensors::CompliancePairProfile& probe, const Options& options,
                  ComplianceOutput& output)
{
    try {
        ImportedRecording recording(path.toStdString(), Mode::Palpation);
        if (const auto problem = unitlessBeam(recording.result().channels)) {
            printError(QStringLiteral("%1: %2").arg(path, *problem));
            return kExitUsage;
        }
        const auto calibrations = options.calibrationPath
                                      ? loadGaugeFactors(options.calibrationPath->toStdString(), probe)
                                      : calibration::recordsFromJsonArray(recording.metadata().calibrationsJson);
        output.sampleRate_hz = recording.result().rate_hz;
        if (options.steps) {
            const auto read = derived::readPalpationForces(recording.store(), recording.session(), probe, calibrations);
            std::vector<double> x, high, low;
            for (const auto& s : read.samples) {
                x.push_back(s.displacement_m);
                high.push_back(s.forceHigh_n);
                low.push_back(s.forceLow_n);
            }
            auto settings = options.stepSettings;
            settings.contactThreshold_n = read.contactThreshold_n;
            output.steps = compliance::readSteps(output.pair(), x, high, low, settings);
            output.basis = toQString(read.basis);
            output.recordedZeros = read.recordedZeros;
        } else {
            auto read = derived::readPalpationPresses(recording.store(), recording.session(), probe, calibrations);
            output.presses = std::move(read.presses);
            output.usableRange_n_per_m = read.usableRange_n_per_m;
            output.basis = toQString(read.basis);
            output.recordedZeros = read.recordedZeros;
        }
    } catch (const std::exception&) {  // the file, a calibration file, channels, too short a recording
        return exitForReadError(path);
    }
    output.source = output.recordedZeros ? QStringLiteral("the recording's zeros")
                                         : QStringLiteral("a zero from the first %1 s, as the live view takes it")
                                               .arg(compliance::LivePalpation::kTare_s);
    return kExitOk;
}

}  // namespace

int runCompliance(const QStringList& arguments)
{
    const QString name = QStringLiteral("compliance");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Object stiffness from a two-beam compliance probe (seed 001).\n"
        "RECORDING.csv is a raw recording — the simulator's, a session export, a probe's CSV with the beams in "
        "counts, strain or N and the displacement in m (units in the header: 'high [count]') — read through "
        "the profile's strain-gauge chain and beam model as the live view reads it; or forces already "
        "computed, in columns displacement_m,force_high_n,force_low_n."));
    parser.addPositionalArgument(QStringLiteral("PROFILE.json"), QStringLiteral("A compliance_pair profile."));
    parser.addPositionalArgument(QStringLiteral("RECORDING.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("calibration"),
         QStringLiteral("Gauge-factor calibration records (JSON) for the beams; default: the recording's own, "
                        "else the nominal gauge factor."),
         QStringLiteral("FILE")},
        {QStringLiteral("steps"),
         QStringLiteral("Read the paper's way: 1 mm steps, 1000 readings each, 3σ rejected once, k_o per step.")},
        {QStringLiteral("readings"), QStringLiteral("Readings per step with --steps (default 1000)."),
         QStringLiteral("N")},
        {QStringLiteral("contact-n"),
         QStringLiteral("Forces form: contact threshold on both forces in N (default 0.01)."), QStringLiteral("F")},
        {QStringLiteral("tissues"), QStringLiteral("Place the reading against the reference tissues in FILE."),
         QStringLiteral("FILE")},
        {QStringLiteral("json"), QStringLiteral("Print one JSON object.")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2)
        return usageError(QStringLiteral("compliance needs PROFILE.json and RECORDING.csv"), usage);
    Options options;
    if (parser.isSet(QStringLiteral("contact-n"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("contact-n")));
        if (!value || *value <= 0.0)
            return usageError(QStringLiteral("--contact-n must be a positive number of newtons"), usage);
        options.contact_n = *value;
    }
    options.steps = parser.isSet(QStringLiteral("steps"));
    if (parser.isSet(QStringLiteral("readings"))) {
        bool ok = false;
        const int readings = parser.value(QStringLiteral("readings")).toInt(&ok);
        if (!ok || readings < 2) return usageError(QStringLiteral("--readings must be an integer of 2 or more"), usage);
        options.stepSettings.readings = static_cast<std::size_t>(readings);
    }
    if (parser.isSet(QStringLiteral("calibration")))
        options.calibrationPath = parser.value(QStringLiteral("calibration"));

    std::optional<sensors::CompliancePairProfile> probe;
    std::vector<compliance::ReferenceTissue> tissues;
    bool forceColumns = false;
    try {
        const auto profile = sensors::loadSensorProfile(positional[0].toStdString());
        const auto* pairProfile = std::get_if<sensors::CompliancePairProfile>(&profile);
        if (!pairProfile) {
            printError(QStringLiteral("%1: kind: a compliance_pair profile is needed").arg(positional[0]));
            return kExitUsage;
        }
        probe = *pairProfile;
        const std::vector<std::string> header = io::CsvReader(positional[1].toStdString()).header();
        forceColumns = std::ranges::find(header, std::string(kForceColumns[1])) != header.end();
        if (parser.isSet(QStringLiteral("tissues")))
            tissues = compliance::loadReferenceTissues(parser.value(QStringLiteral("tissues")).toStdString());
    } catch (const std::runtime_error& e) {  // profile, CSV and tissue errors
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    ComplianceOutput output(*probe);
    if (forceColumns && options.calibrationPath)
        return usageError(QStringLiteral("--calibration applies to raw recordings, not to forces"), usage);
    const int read = forceColumns ? readForceColumns(positional[1], output.pair(), options, output)
                                  : readRecording(positional[1], *probe, options, output);
    if (read != kExitOk) return read;
    output.tissues = std::move(tissues);
    return output.print(parser.isSet(QStringLiteral("json")));
}

}  // namespace tactiscope::cli
