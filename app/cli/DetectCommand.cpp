// The detect subcommand: options → DetectorParameters, CSV in, CSV/JSON out.
#include "DetectCommand.h"

#include "CliSupport.h"
#include "DetectorOptions.h"
#include "core/detector/OfflineDetection.h"
#include "core/detector/PartialCorrelationKernel.h"
#include "core/detector/StreamingDetection.h"
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

constexpr const char* kOutputHeader = "t,out,rab,rba,lag_ab_ms,lag_ba_ms\n";

// Appends one output row per sample to `line` (cleared first).
void appendOutputRows(std::string& text, std::span<const ProbeOutput> outputs, double dt_s)
{
    text.clear();
    for (const ProbeOutput& p : outputs) {
        const auto& o = p.combined;
        core::text::appendShortest(text, p.t_s);
        text += ',';
        text += std::to_string(o.decision);
        text += ',';
        core::text::appendShortest(text, o.rab);
        text += ',';
        core::text::appendShortest(text, o.rba);
        text += ',';
        core::text::appendShortest(text, lag_ms(o.lagAb, dt_s));
        text += ',';
        core::text::appendShortest(text, lag_ms(o.lagBa, dt_s));
        text += '\n';
    }
}

// A failure inside the stream, with the exit code it ends the command with.
struct DetectFailure {
    QString message;
    int exit;
};

struct DetectResult {
    std::size_t samples = 0;
    std::size_t lags = 0;
    double interval_s = 0.0;  // the whole file's mean
    double elapsed_s = 0.0;   // in the detector alone
    std::vector<DefectEvent> events;
};

// Reads the file a block at a time into the streaming detector; per-sample
// rows go to `out` as they come when it is given. Throws DetectFailure.
DetectResult detectStream(const DetectOptions& options, std::ostream* out)
{
    const QString& input = options.input;
    DetectResult result;
    try {
        core::io::CsvColumnReader reader(input.toStdString(), options.columns);
        constexpr std::size_t kBlock = core::detector::StreamingDetection::kChunk;
        std::vector<std::vector<double>> block;
        std::vector<std::size_t> lines;
        if (reader.read(kBlock, block, lines) == 0)
            throw DetectFailure{QStringLiteral("'%1' has a header but no data rows").arg(input), kExitUsage};
        core::io::UniformTimeBaseCheck timeBase;
        const auto checkTimes = [&] {
            try {
                timeBase.add(block.front());
            } catch (const core::io::TimeBaseError& e) {
                throw DetectFailure{QStringLiteral("'%1' line %2: %3")
                                        .arg(input)
                                        .arg(lines[e.row()])
                                        .arg(QString::fromStdString(e.what())),
                                    kExitUsage};
            }
        };
        checkTimes();
        // The lags in samples from the first block's interval; the events'
        // seconds are restated with the whole file's at the end.
        DetectorParameters parameters = options.detector.parameters;
        parameters.sampleInterval_s = timeBase.interval_s();
        const double usedInterval_s = parameters.sampleInterval_s;
        try {
            result.lags = core::detector::resolve(parameters).lags.size();
        } catch (const std::invalid_argument& e) {
            throw DetectFailure{QString::fromStdString(e.what()), kExitUsage};
        }
        std::string rows;
        if (out) *out << kOutputHeader;
        core::detector::StreamingDetection detection(
            block.size() - 1,
            {parameters, options.detector.hold_s, options.detector.spacing_m, options.detector.threads}, 0.0,
            [&](std::uint64_t, std::span<const ProbeOutput> outputs) {
                if (!out) return;
                appendOutputRows(rows, outputs, usedInterval_s);
                *out << rows;
            });
        do {
            core::detector::SeriesInput series{0.0, {block.begin() + 1, block.end()}, block.front()};
            if (const auto bad = core::detector::firstUnusableSample(series)) {
                const auto [cantilever, index] = *bad;
                throw DetectFailure{
                    QStringLiteral("'%1' line %2, column '%3': %4 is beyond what the detector can use (|value| ≤ %5)")
                        .arg(input)
                        .arg(lines[index])
                        .arg(QString::fromStdString(options.columns[cantilever + 1]))
                        .arg(series.cantilevers[cantilever][index])
                        .arg(core::detector::kLargestUsableValue),
                    kExitUsage};
            }
            const auto started = std::chrono::steady_clock::now();
            detection.push(series.cantilevers, block.front());
            result.elapsed_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            if (reader.read(kBlock, block, lines) == 0) break;
            checkTimes();
        } while (true);
        result.samples = static_cast<std::size_t>(detection.samplesPushed());
        result.events = detection.finish().events;
        result.interval_s = timeBase.interval_s();
        core::detector::restateLags(result.events, usedInterval_s, result.interval_s, options.detector.spacing_m);
    } catch (const core::io::CsvError& e) {
        throw DetectFailure{QString::fromStdString(e.what()), kExitUsage};
    }
    return result;
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

    DetectResult result;
    try {
        if (options.output.isEmpty()) {
            result = detectStream(options, nullptr);
        } else {
            core::storage::writeAtomically(options.output.toStdString(),
                                           [&](std::ostream& out) { result = detectStream(options, &out); });
        }
    } catch (const DetectFailure& failure) {
        printError(failure.message);
        return failure.exit;
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    if (options.detector.json) {
        std::cout << eventsJson(result.samples, result.lags, result.elapsed_s, result.events, options.detector) << '\n';
    } else {
        printDetection(options.input, result.samples, result.interval_s, result.lags, result.elapsed_s, result.events,
                       options.detector);
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
