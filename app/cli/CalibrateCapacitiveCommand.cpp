// The calibrate-capacitive subcommand: a calibration recording (raw
// capacitance with its loads, or rows of force and capacitance) to C0, the
// sensitivity, the drift, the hysteresis and the detection limit.
#include "CalibrateCapacitiveCommand.h"

#include "CliSupport.h"
#include "RecordingImport.h"
#include "core/calibration/CapacitiveSteps.h"
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"
#include "core/text/JsonWriter.h"
#include "core/text/UncertaintyFormat.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace tactiscope::cli {
namespace {

using namespace core;

// Farads per unit of a capacitance column; none for another unit.
std::optional<double> faradsPer(const std::string& unit)
{
    for (const auto& [name, scale] : {std::pair{"F", 1.0}, {"nF", 1e-9}, {"pF", 1e-12}, {"fF", 1e-15}})
        if (unit == name) return scale;
    return std::nullopt;
}

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
    if (!scale) return QStringLiteral("capacitance in '%1': use F, nF, pF or fF").arg(toQString(capacitanceUnit));
    double loadScale = 1.0;
    if (load) {
        const std::string& u = channels[*load].unit;
        loadScale = u == "mN" ? 1e-3 : (u == "uN" || u == "µN") ? 1e-6 : 1.0;
    }
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

void writeJson(const calibration::CapacitiveCalibrationResult& result, const calibration::CapacitiveSteps& steps,
               bool timed)
{
    text::JsonWriter json;
    json.beginObject();
    for (const auto& [key, value] : result.record.values) {
        if (key == "drift_pf_per_s" && !timed) continue;  // no time base: no drift
        json.key(key).value(value);
    }
    json.key("sensitivity_standard_error_pf_per_mn").value(result.forceFit->slopeStandardError * 1e9);
    json.key("detection_limit_mgf").value(*result.detectionLimit_n / calibration::kMilligramForce_n);
    json.key("baseline_samples").value(static_cast<long long>(steps.input.baseline.count));
    if (steps.finalShift_f) json.key("final_baseline_shift_pf").value(*steps.finalShift_f * 1e12);
    json.key("points").value(static_cast<long long>(result.forceFit->points));
    json.key("steps_unsettled").value(static_cast<long long>(steps.unsettled));
    json.key("cautions").beginArray();
    for (const std::string& caution : result.cautions) json.value(caution);
    json.endArray();
    json.key("steps").beginArray();
    for (const auto& step : steps.steps) {
        json.beginObject();
        json.key("force_n").value(step.force_n);
        json.key("loading").value(step.loading);
        json.key("capacitance_pf").value(step.window.mean * 1e12);
        json.key("samples").value(static_cast<long long>(step.window.count));
        if (timed) {
            json.key("start_s").value(step.window.start_s);
            json.key("end_s").value(step.window.end_s);
        }
        json.endObject();
    }
    json.endArray();
    json.endObject();
    std::cout << json.str() << '\n';
}

void writeText(const calibration::CapacitiveCalibrationResult& result, const calibration::CapacitiveSteps& steps,
               bool timed)
{
    QTextStream out(stdout);
    out << "C0: " << QString::number(result.c0_f * 1e12, 'f', 4) << " pF (baseline σ "
        << QString::number(result.baselineSigma_f * 1e12, 'f', 4) << " pF over " << steps.input.baseline.count
        << (timed ? " samples of the first baseline)\n" : " rows of the first baseline)\n");
    if (steps.finalShift_f) {
        if (timed)
            out << "drift: " << QString::number(result.drift_f_per_s * 1e12, 'g', 3) << " pF/s (the final baseline is "
                << QString::number(*steps.finalShift_f * 1e12, 'f', 4)
                << " pF from C0), removed before ΔC and the hysteresis\n";
        else
            out << "final baseline " << QString::number(*steps.finalShift_f * 1e12, 'f', 4)
                << " pF from C0: not removed (no time column to spread it over)\n";
    }
    const auto& fit = *result.forceFit;
    out << "sensitivity: " << toQString(text::valueWithUncertainty(fit.slope * 1e9, fit.slopeStandardError * 1e9))
        << " pF/mN, intercept " << QString::number(fit.intercept * 1e12, 'f', 4) << " pF, R² "
        << QString::number(fit.rSquared, 'f', 5) << " (" << fit.points << " points)\n";
    out << "relative sensitivity: " << QString::number(*result.relativeSensitivity_per_n * 1e-3, 'f', 4) << " per mN";
    if (result.pressureSensitivity_per_pa)
        out << ", " << QString::number(*result.pressureSensitivity_per_pa * 1e3, 'f', 3) << " per kPa";
    out << "\ndetection limit: " << QString::number(*result.detectionLimit_n * 1e6, 'f', 1) << " µN ("
        << QString::number(*result.detectionLimit_n / calibration::kMilligramForce_n, 'f', 2) << " mgf, 3σ of C0)\n";
    if (result.hysteresis)
        out << "hysteresis: " << QString::number(*result.hysteresis * 100.0, 'f', 2) << " % of full scale\n";
    const auto unloading = std::ranges::count_if(steps.steps, [](const auto& s) { return !s.loading; });
    out << "steps: " << steps.steps.size() - static_cast<std::size_t>(unloading) << " loading, " << unloading
        << " unloading";
    if (steps.unsettled > 0) out << ", " << steps.unsettled << " never settled (left out)";
    out << '\n';
    for (const std::string& caution : result.cautions) out << "caution: " << QString::fromStdString(caution) << '\n';
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
        "C0 and its noise, the last the drift, removed before the hysteresis."));
    parser.addPositionalArgument(QStringLiteral("RECORDING.csv"), QStringLiteral("The calibration recording."));
    parser.addOptions({
        {QStringLiteral("loads-mgf"),
         QStringLiteral("The loads placed, in order, in mgf, the unloaded baseline first (0,10,20,…,0)."),
         QStringLiteral("LIST")},
        {QStringLiteral("unit"), QStringLiteral("Unit of a capacitance column without one: F or pF."),
         QStringLiteral("UNIT")},
        {QStringLiteral("contact-area-mm2"), QStringLiteral("Contact area for the pressure sensitivity (e.g. 9)."),
         QStringLiteral("A")},
        {QStringLiteral("json"), QStringLiteral("Print one JSON object.")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (parser.positionalArguments().size() != 1)
        return usageError(QStringLiteral("calibrate-capacitive needs RECORDING.csv"), usage);
    std::optional<double> area_m2;
    if (parser.isSet(QStringLiteral("contact-area-mm2"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("contact-area-mm2")));
        if (!value || *value <= 0.0)
            return usageError(QStringLiteral("--contact-area-mm2 must be a positive number"), usage);
        area_m2 = *value * 1e-6;
    }
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
        writeJson(result, steps, timed);
    else
        writeText(result, steps, timed);
    return kExitOk;
}

}  // namespace tactiscope::cli
