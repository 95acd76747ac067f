// The calibrate-capacitive subcommand.
#include "CalibrateCapacitiveCommand.h"

#include "CliSupport.h"
#include "core/calibration/CapacitiveCalibration.h"
#include "core/compliance/RobustMean.h"
#include "core/io/CsvColumns.h"
#include "core/text/JsonWriter.h"

#include <QTextStream>

#include <iostream>

namespace tactiscope::cli {

int runCalibrateCapacitive(const QStringList& arguments)
{
    using namespace core;
    const QString name = QStringLiteral("calibrate-capacitive");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "C0 and sensitivity of a capacitive beam (seed 002) from READINGS.csv with columns force_n,capacitance_pf.\n"
        "Rows with force 0 form the baseline; a row whose force is below the previous row's counts as unloading."));
    parser.addPositionalArgument(QStringLiteral("READINGS.csv"), QStringLiteral("The recorded readings."));
    parser.addOptions({
        {QStringLiteral("contact-area-mm2"), QStringLiteral("Contact area for the pressure sensitivity (e.g. 9)."),
         QStringLiteral("A")},
        {QStringLiteral("json"), QStringLiteral("Print one JSON object.")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (parser.positionalArguments().size() != 1)
        return usageError(QStringLiteral("calibrate-capacitive needs READINGS.csv"), usage);
    std::optional<double> area_m2;
    if (parser.isSet(QStringLiteral("contact-area-mm2"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("contact-area-mm2")));
        if (!value || *value <= 0.0)
            return usageError(QStringLiteral("--contact-area-mm2 must be a positive number"), usage);
        area_m2 = *value * 1e-6;
    }
    const QString path = parser.positionalArguments().front();
    io::CsvColumns csv;
    try {
        csv = io::readCsvColumns(path.toStdString(), {"force_n", "capacitance_pf"});
    } catch (const io::CsvError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    std::vector<double> baseline;
    calibration::CapacitiveCalibrationInput input;
    input.contactArea_m2 = area_m2;
    double previousForce = 0.0;
    for (std::size_t i = 0; i < csv.rowCount(); ++i) {
        const double force = csv.columns[0][i];
        const double c_f = csv.columns[1][i] * 1e-12;
        if (force < 0.0) {
            printError(QStringLiteral("'%1' line %2: force must not be negative").arg(path).arg(csv.lines[i]));
            return kExitUsage;
        }
        if (force == 0.0) {
            baseline.push_back(c_f);
        } else {
            input.steps.push_back({force, std::nullopt, c_f, static_cast<double>(i), force >= previousForce});
        }
        previousForce = force;
    }
    if (baseline.size() < 2) {
        printError(QStringLiteral("'%1': at least two rows with force 0 are needed for the baseline").arg(path));
        return kExitUsage;
    }
    const auto base = compliance::robustMean(baseline);
    input.baseline.mean = base.mean;
    input.baseline.sigma = base.standardDeviation;
    calibration::CapacitiveCalibrationResult result;
    try {
        result = calibration::calibrateCapacitive(input, path.toStdString(), "");
    } catch (const std::invalid_argument& e) {
        printError(QStringLiteral("'%1': %2").arg(path, QString::fromStdString(e.what())));
        return kExitUsage;
    }
    if (!(result.forceFit->slope > 0.0)) {
        printError(QStringLiteral("'%1': capacitance does not rise with force; check the columns").arg(path));
        return kExitUsage;
    }

    text::JsonWriter json;
    json.beginObject();
    for (const auto& [key, value] : result.record.values) {
        if (key == "drift_pf_per_s") continue;  // no time base in this file
        json.key(key).value(value);
    }
    json.key("points").value(static_cast<long long>(result.forceFit->points));
    json.endObject();
    if (parser.isSet(QStringLiteral("json"))) {
        std::cout << json.str() << '\n';
        return kExitOk;
    }
    QTextStream out(stdout);
    out << "C0: " << QString::number(result.c0_f * 1e12, 'f', 3) << " pF (baseline σ "
        << QString::number(result.baselineSigma_f * 1e12, 'f', 4) << " pF over " << baseline.size() << " rows)\n";
    out << "sensitivity: " << QString::number(result.forceFit->slope * 1e9, 'f', 4) << " pF/mN, intercept "
        << QString::number(result.forceFit->intercept * 1e12, 'f', 4) << " pF, R² "
        << QString::number(result.forceFit->rSquared, 'f', 5) << '\n';
    out << "relative sensitivity: " << QString::number(*result.relativeSensitivity_per_n * 1e-3, 'f', 4) << " per mN";
    if (result.pressureSensitivity_per_pa)
        out << ", " << QString::number(*result.pressureSensitivity_per_pa * 1e3, 'f', 3) << " per kPa";
    out << "\ndetection limit: " << QString::number(*result.detectionLimit_n * 1e6, 'f', 1) << " µN ("
        << QString::number(*result.detectionLimit_n / calibration::kMilligramForce_n, 'f', 2) << " mgf)\n";
    if (result.hysteresis)
        out << "hysteresis: " << QString::number(*result.hysteresis * 100.0, 'f', 2) << " % of full scale\n";
    return kExitOk;
}

}  // namespace tactiscope::cli
