// The detect subcommand: options → DetectorParameters, CSV in, CSV/JSON out.
#include "DetectCommand.h"

#include "CliSupport.h"
#include "DetectorOptions.h"
#include "core/detector/OfflineDetection.h"
#include "core/detector/PartialCorrelationKernel.h"
#include "core/io/CsvColumns.h"
#include "core/io/UniformTimeBase.h"
#include "core/storage/Database.h"
#include "core/storage/SafeOutput.h"
#include "core/text/JsonWriter.h"
#include "core/text/NumberFormat.h"

#include <QTextStream>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <thread>

namespace tactiscope::cli {
namespace {

using core::detector::DefectEvent;
using core::detector::DetectorParameters;
using core::detector::ProbeOutput;

struct DetectOptions {
    QString input;
    QString output;
    std::vector<std::string> columns{"t", "a", "b"};
    DetectorOptions detector;
};

// Fills `options` from the parser; returns an error message or nothing.
std::optional<QString> readOptions(const QCommandLineParser& parser, DetectOptions& options)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) return QStringLiteral("detect needs exactly one INPUT.csv");
    options.input = positional.front();
    options.output = parser.value(QStringLiteral("output"));
    if (parser.isSet(QStringLiteral("columns"))) {
        options.columns.clear();
        for (const QString& name : parser.value(QStringLiteral("columns")).split(QLatin1Char(',')))
            options.columns.push_back(name.trimmed().toStdString());
        if (options.columns.size() < 3)
            return QStringLiteral("--columns needs a time column and at least two cantilevers, e.g. T,A,B");
    }
    return readDetectorOptions(parser, options.detector);
}

// A lag in milliseconds, rounded to 1 ns so that k·Δt prints as "52", not
// "52.00000000000001".
double lag_ms(std::uint32_t samples, double dt_s)
{
    return std::round(static_cast<double>(samples) * dt_s * 1e9) / 1e6;
}

void writeOutputCsv(std::ostream& out, std::span<const double> t, std::span<const ProbeOutput> outputs, double dt_s)
{
    std::string line = "t,out,rab,rba,lag_ab_ms,lag_ba_ms\n";
    out << line;
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& o = outputs[i].combined;
        line.clear();
        core::text::appendShortest(line, t[i]);
        line += ',';
        line += std::to_string(o.decision);
        line += ',';
        core::text::appendShortest(line, o.rab);
        line += ',';
        core::text::appendShortest(line, o.rba);
        line += ',';
        core::text::appendShortest(line, lag_ms(o.lagAb, dt_s));
        line += ',';
        core::text::appendShortest(line, lag_ms(o.lagBa, dt_s));
        line += '\n';
        out << line;
    }
}

}  // namespace

int runDetect(const QStringList& arguments)
{
    const QString name = QStringLiteral("detect");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Run the surface-deflection detector (partial correlation, seed 000) over a CSV recording.\n"
                       "INPUT.csv has a header and columns t,a,b (t in seconds, a and b dimensionless strain)."));
    parser.addPositionalArgument(QStringLiteral("INPUT.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("columns"), QStringLiteral("Time and cantilever columns, in probe order (default t,a,b)."),
         QStringLiteral("T,A,B")},
        {QStringLiteral("output"), QStringLiteral("Write t,out,rab,rba,lag_ab_ms,lag_ba_ms per sample to OUT.csv."),
         QStringLiteral("OUT.csv")},
    });
    addDetectorOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);

    DetectOptions options;
    if (const auto error = readOptions(parser, options)) return usageError(*error, usage);
    try {
        if (!options.output.isEmpty())
            core::storage::refuseOverwriting(options.output.toStdString(), {options.input.toStdString()});
    } catch (const core::storage::StorageError& e) {
        return usageError(QString::fromStdString(e.what()), usage);
    }

    core::io::CsvColumns csv;
    try {
        csv = core::io::readCsvColumns(options.input.toStdString(), options.columns);
    } catch (const core::io::CsvError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }
    const std::vector<double>& t = csv.columns.front();
    try {
        options.detector.parameters.sampleInterval_s = core::io::uniformSampleInterval(t);
    } catch (const core::io::TimeBaseError& e) {
        printError(QStringLiteral("'%1' line %2: %3")
                       .arg(options.input)
                       .arg(csv.lines[e.row()])
                       .arg(QString::fromStdString(e.what())));
        return kExitUsage;
    }
    std::size_t lagCount = 0;
    try {
        lagCount = core::detector::resolve(options.detector.parameters).lags.size();
    } catch (const std::invalid_argument& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    core::detector::SeriesInput series{t.front(), {}, t};
    for (std::size_t c = 1; c < csv.columns.size(); ++c) series.cantilevers.emplace_back(csv.columns[c]);
    if (const auto bad = core::detector::firstUnusableSample(series)) {
        const auto [cantilever, index] = *bad;
        printError(QStringLiteral("'%1' line %2, column '%3': %4 is beyond what the detector can use (|value| ≤ %5)")
                       .arg(options.input)
                       .arg(csv.lines[index])
                       .arg(QString::fromStdString(options.columns[cantilever + 1]))
                       .arg(series.cantilevers[cantilever][index])
                       .arg(core::detector::kLargestUsableValue));
        return kExitUsage;
    }
    const auto started = std::chrono::steady_clock::now();
    const auto outputs = core::detector::detectSeries(series, options.detector.parameters, options.detector.threads);
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double dt = options.detector.parameters.sampleInterval_s;
    const auto events = core::detector::segmentEvents(outputs, dt, options.detector.hold_s, options.detector.spacing_m);

    if (!options.output.isEmpty()) {
        try {
            core::storage::writeAtomically(options.output.toStdString(),
                                           [&](std::ostream& out) { writeOutputCsv(out, t, outputs, dt); });
        } catch (const core::storage::StorageError& e) {
            printError(QString::fromStdString(e.what()));
            return kExitFailure;
        }
    }
    if (options.detector.json) {
        std::cout << eventsJson(outputs.size(), lagCount, elapsed_s, events, options.detector) << '\n';
    } else {
        printDetection(options.input, outputs.size(), dt, lagCount, elapsed_s, events, options.detector);
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
