// The detect subcommand: options → DetectorParameters, CSV in, CSV/JSON out.
#include "DetectCommand.h"

#include "CliSupport.h"
#include "core/detector/OfflineDetection.h"
#include "core/detector/PartialCorrelationKernel.h"
#include "core/io/CsvColumns.h"
#include "core/io/UniformTimeBase.h"
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
    bool json = false;
    std::vector<std::string> columns{"t", "a", "b"};
    DetectorParameters parameters;
    double hold_s = 0.020;
    std::optional<double> spacing_m;
    unsigned threads = 1;
};

// Fills `options` from the parser; returns an error message or nothing.
std::optional<QString> readOptions(const QCommandLineParser& parser, DetectOptions& options)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) return QStringLiteral("detect needs exactly one INPUT.csv");
    options.input = positional.front();
    options.output = parser.value(QStringLiteral("output"));
    options.json = parser.isSet(QStringLiteral("json"));
    options.parameters.faceToFace = parser.isSet(QStringLiteral("face-to-face"));

    if (parser.isSet(QStringLiteral("columns"))) {
        options.columns.clear();
        for (const QString& name : parser.value(QStringLiteral("columns")).split(QLatin1Char(',')))
            options.columns.push_back(name.trimmed().toStdString());
        if (options.columns.size() < 3)
            return QStringLiteral("--columns needs a time column and at least two cantilevers, e.g. T,A,B");
    }
    if (parser.isSet(QStringLiteral("lags-ms"))) {
        const QStringList parts = parser.value(QStringLiteral("lags-ms")).split(QLatin1Char(':'));
        std::optional<double> start, stop, step;
        if (parts.size() == 3) {
            start = parseNumber(parts[0]);
            stop = parseNumber(parts[1]);
            step = parseNumber(parts[2]);
        }
        if (!start || !stop || !step)
            return QStringLiteral("--lags-ms must be START:STOP:STEP in milliseconds, got '%1'")
                .arg(parser.value(QStringLiteral("lags-ms")));
        try {
            options.parameters.lags_s = core::detector::lagRange_s(*start * 1e-3, *stop * 1e-3, *step * 1e-3);
        } catch (const std::invalid_argument& e) {
            return QStringLiteral("bad --lags-ms: %1").arg(QString::fromStdString(e.what()));
        }
    }
    if (parser.isSet(QStringLiteral("lambda-ms"))) {
        const QString lambda = parser.value(QStringLiteral("lambda-ms"));
        if (lambda != QLatin1String("lag")) {
            const auto value = parseNumber(lambda);
            if (!value || *value <= 0.0)
                return QStringLiteral("--lambda-ms must be 'lag' or a positive number, got '%1'").arg(lambda);
            options.parameters.lambdaRule = core::detector::LambdaRule::Fixed;
            options.parameters.fixedLambda_s = *value * 1e-3;
        }
    }
    const auto number = [&](const char* name, double& target, double scale) -> std::optional<QString> {
        if (!parser.isSet(QString::fromLatin1(name))) return std::nullopt;
        const auto value = parseNumber(parser.value(QString::fromLatin1(name)));
        if (!value)
            return QStringLiteral("--%1 must be a number, got '%2'")
                .arg(QString::fromLatin1(name), parser.value(QString::fromLatin1(name)));
        target = *value * scale;
        return std::nullopt;
    };
    double window_ms = 0.0, spacing_mm = 0.0, hold_ms = options.hold_s * 1e3;
    for (const auto& error :
         {number("epsilon", options.parameters.epsilon, 1.0), number("threshold", options.parameters.threshold, 1.0),
          number("window-ms", window_ms, 1.0), number("spacing-mm", spacing_mm, 1.0),
          number("hold-ms", hold_ms, 1.0)}) {
        if (error) return error;
    }
    if (parser.isSet(QStringLiteral("window-ms"))) options.parameters.window_s = window_ms * 1e-3;
    if (parser.isSet(QStringLiteral("spacing-mm"))) {
        if (!(spacing_mm > 0.0)) return QStringLiteral("--spacing-mm must be positive");
        options.spacing_m = spacing_mm * 1e-3;
    }
    if (!(hold_ms >= 0.0)) return QStringLiteral("--hold-ms must not be negative");
    options.hold_s = hold_ms * 1e-3;
    if (parser.isSet(QStringLiteral("threads"))) {
        bool ok = false;
        const int threads = parser.value(QStringLiteral("threads")).toInt(&ok);
        if (!ok || threads < 1 || threads > 256)
            return QStringLiteral("--threads must be a whole number from 1 to 256");
        options.threads = static_cast<unsigned>(threads);
    }
    return std::nullopt;
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

const char* order(int direction)
{
    return direction > 0 ? "A then B" : "B then A";
}

std::string eventsJson(std::size_t samples, std::size_t lags, double elapsed_s, const std::vector<DefectEvent>& events,
                       const DetectOptions& options)
{
    core::text::JsonWriter json;
    json.beginObject();
    json.key("samples").value(static_cast<long long>(samples));
    json.key("lags").value(static_cast<long long>(lags));
    json.key("elapsed_s").value(elapsed_s);
    json.key("samples_per_s").value(elapsed_s > 0.0 ? static_cast<double>(samples) / elapsed_s : 0.0);
    json.key("kernel").value(core::detector::toString(core::detector::bestKernelVariant()));
    json.key("threads").value(static_cast<long long>(options.threads));
    json.key("events").beginArray();
    for (const DefectEvent& e : events) {
        json.beginObject();
        json.key("start_s").value(e.start_s);
        json.key("end_s").value(e.end_s);
        json.key("direction").value(static_cast<long long>(e.direction));
        json.key("order").value(order(e.direction));
        json.key("peak_r").value(e.peakR);
        json.key("lag_ms").value(std::round(e.peakLag_s * 1e9) / 1e6);
        if (e.speed_m_per_s) json.key("speed_mm_s").value(*e.speed_m_per_s * 1e3);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.str();
}

void printSummary(const QString& input, std::size_t samples, double dt_s, std::size_t lags, double elapsed_s,
                  const std::vector<DefectEvent>& events, const DetectOptions& options)
{
    QTextStream out(stdout);
    const auto& p = options.parameters;
    out << input << ": " << samples << " samples at " << QString::number(1.0 / dt_s, 'g', 6) << " Hz, " << lags
        << " lags, "
        << (p.window_s ? QStringLiteral("sliding window of %1 ms").arg(*p.window_s * 1e3)
                       : QStringLiteral("exponential weighting"))
        << '\n';
    out << "detection: " << QString::number(elapsed_s * 1e3, 'f', 1) << " ms ("
        << QString::number(static_cast<double>(samples) / elapsed_s / 1e6, 'f', 2) << " M samples/s) on "
        << core::detector::toString(core::detector::bestKernelVariant()) << ", " << options.threads
        << (options.threads == 1 ? " thread\n" : " threads\n");
    out << events.size() << (events.size() == 1 ? " event" : " events") << (events.empty() ? "\n" : ":\n");
    if (events.empty()) return;
    out << qSetFieldWidth(12) << "start_s"
        << "end_s"
        << "order"
        << "peak_R"
        << "lag_ms";
    if (options.spacing_m) out << "speed_mm_s";
    out << qSetFieldWidth(0) << '\n';
    for (const DefectEvent& e : events) {
        out << qSetFieldWidth(12) << QString::number(e.start_s, 'f', 3) << QString::number(e.end_s, 'f', 3)
            << order(e.direction) << QString::number(e.peakR, 'f', 3) << QString::number(e.peakLag_s * 1e3, 'f', 1);
        if (e.speed_m_per_s) out << QString::number(*e.speed_m_per_s * 1e3, 'f', 0);
        out << qSetFieldWidth(0) << '\n';
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
        {QStringLiteral("lags-ms"), QStringLiteral("Lag range in ms (default 2:150:2)."),
         QStringLiteral("START:STOP:STEP")},
        {QStringLiteral("lambda-ms"), QStringLiteral("Forgetting time λ: 'lag' (λ = c, default) or a value in ms."),
         QStringLiteral("lag|VALUE")},
        {QStringLiteral("epsilon"), QStringLiteral("Regularisation ε in strain (default 7e-6)."), QStringLiteral("E")},
        {QStringLiteral("threshold"), QStringLiteral("Decision threshold on R (default 0.85)."), QStringLiteral("T")},
        {QStringLiteral("face-to-face"), QStringLiteral("The gauges face each other: negate b.")},
        {QStringLiteral("window-ms"),
         QStringLiteral("Use the sliding-window form over H ms instead of exponential weighting."),
         QStringLiteral("H")},
        {QStringLiteral("spacing-mm"), QStringLiteral("Cantilever spacing, to report the scan speed of each event."),
         QStringLiteral("D")},
        {QStringLiteral("hold-ms"), QStringLiteral("Bridge gaps up to H ms within an event (default 20)."),
         QStringLiteral("H")},
        {QStringLiteral("threads"), QStringLiteral("Worker threads (default 1)."), QStringLiteral("N")},
        {QStringLiteral("output"), QStringLiteral("Write t,out,rab,rba,lag_ab_ms,lag_ba_ms per sample to OUT.csv."),
         QStringLiteral("OUT.csv")},
        {QStringLiteral("json"),
         QStringLiteral("Print one JSON object: samples, lags, elapsed_s, samples_per_s, events.")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);

    DetectOptions options;
    if (const auto error = readOptions(parser, options)) return usageError(*error, usage);

    core::io::CsvColumns csv;
    try {
        csv = core::io::readCsvColumns(options.input.toStdString(), options.columns);
    } catch (const core::io::CsvError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }
    const std::vector<double>& t = csv.columns.front();
    try {
        options.parameters.sampleInterval_s = core::io::uniformSampleInterval(t);
    } catch (const core::io::TimeBaseError& e) {
        printError(QStringLiteral("'%1' line %2: %3")
                       .arg(options.input)
                       .arg(csv.lines[e.row()])
                       .arg(QString::fromStdString(e.what())));
        return kExitUsage;
    }
    std::size_t lagCount = 0;
    try {
        lagCount = core::detector::resolve(options.parameters).lags.size();
    } catch (const std::invalid_argument& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    core::detector::SeriesInput series{t.front(), {}, t};
    for (std::size_t c = 1; c < csv.columns.size(); ++c) series.cantilevers.emplace_back(csv.columns[c]);
    const auto started = std::chrono::steady_clock::now();
    const auto outputs = core::detector::detectSeries(series, options.parameters, options.threads);
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double dt = options.parameters.sampleInterval_s;
    const auto events = core::detector::segmentEvents(outputs, dt, options.hold_s, options.spacing_m);

    if (!options.output.isEmpty()) {
        std::ofstream file(options.output.toStdString(), std::ios::binary | std::ios::trunc);
        if (file) writeOutputCsv(file, t, outputs, dt);
        file.close();
        if (!file) {
            printError(QStringLiteral("cannot write '%1': %2")
                           .arg(options.output, QString::fromLocal8Bit(std::strerror(errno))));
            return kExitFailure;
        }
    }
    if (options.json) {
        std::cout << eventsJson(outputs.size(), lagCount, elapsed_s, events, options) << '\n';
    } else {
        printSummary(options.input, outputs.size(), dt, lagCount, elapsed_s, events, options);
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
