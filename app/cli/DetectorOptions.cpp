// Detector options and event output shared by detect and analyze.
#include "DetectorOptions.h"

#include "CliSupport.h"
#include "core/detector/DefectOrder.h"
#include "core/detector/DefectSitesJson.h"
#include "core/detector/PartialCorrelationKernel.h"
#include "core/text/JsonWriter.h"

#include <QTextStream>

#include <cmath>

namespace tactiscope::cli {
namespace {

// What ran: the probe's kernel, or the workstation's in the instruction set it chose.
const char* kernelName(const DetectorOptions& options)
{
    return options.engine == core::detector::DetectorEngine::Probe
               ? "probe (single precision)"
               : core::detector::toString(core::detector::bestKernelVariant());
}

unsigned threadsUsed(const DetectorOptions& options)
{
    return options.engine == core::detector::DetectorEngine::Probe ? 1U : options.threads;
}

using core::detector::DefectEvent;

}  // namespace

void addDetectorOptions(QCommandLineParser& parser)
{
    parser.addOptions({
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
        {QStringLiteral("spacing-mm"),
         QStringLiteral("Cantilever spacing (the paper's probe: 15 mm): each event's scan speed, which "
                        "places sites by their phase; a position channel's sites take a doubt of 5 % of it."),
         QStringLiteral("D")},
        {QStringLiteral("hold-ms"), QStringLiteral("Bridge gaps up to H ms within an event (default 20)."),
         QStringLiteral("H")},
        {QStringLiteral("threads"), QStringLiteral("Worker threads (default 1)."), QStringLiteral("N")},
        {QStringLiteral("json"),
         QStringLiteral("Print one JSON object: samples, lags, elapsed_s, samples_per_s, events, and the defect sites "
                        "(sites, sites_method: docs/detector.md).")},
    });
}

std::optional<QString> readDetectorOptions(const QCommandLineParser& parser, DetectorOptions& options)
{
    options.json = parser.isSet(QStringLiteral("json"));
    options.parameters.faceToFace = parser.isSet(QStringLiteral("face-to-face"));

    if (parser.isSet(QStringLiteral("lags-ms"))) {
        const QStringList parts = parser.value(QStringLiteral("lags-ms")).split(QLatin1Char(':'));
        std::optional<double> start, stop, step;
        if (parts.size() == 3) {
            start = parseNumber(parts[0]);
            stop = parseNumber(parts[1]);
            step = parseNumber(parts[2]);
        }
        if (!start || !stop || !step)
            return QStringLiteral("--lags-ms must be START:STOP:STEP in milliseconds, got %1")
                .arg(quoted(parser.value(QStringLiteral("lags-ms"))));
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
                return QStringLiteral("--lambda-ms must be 'lag' or a positive number, got %1").arg(quoted(lambda));
            options.parameters.lambdaRule = core::detector::LambdaRule::Fixed;
            options.parameters.fixedLambda_s = *value * 1e-3;
        }
    }
    const auto number = [&](const char* name, double& target, double scale) -> std::optional<QString> {
        if (!parser.isSet(QString::fromLatin1(name))) return std::nullopt;
        const auto value = parseNumber(parser.value(QString::fromLatin1(name)));
        if (!value)
            return QStringLiteral("--%1 must be a number, got %2")
                .arg(QString::fromLatin1(name), quoted(parser.value(QString::fromLatin1(name))));
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

std::string eventsJson(const DetectionOutput& output, const DetectorOptions& options,
                       const std::optional<core::detector::ProbeAgreement>& probe)
{
    const auto [samples, lags, elapsed_s, events, sites] = output;
    core::text::JsonWriter json;
    json.beginObject();
    json.key("samples").value(static_cast<long long>(samples));
    json.key("lags").value(static_cast<long long>(lags));
    json.key("elapsed_s").value(elapsed_s);
    json.key("samples_per_s").value(elapsed_s > 0.0 ? static_cast<double>(samples) / elapsed_s : 0.0);
    json.key("kernel").value(kernelName(options));
    json.key("threads").value(static_cast<long long>(threadsUsed(options)));
    json.key("events").beginArray();
    for (const DefectEvent& e : events) {
        json.beginObject();
        json.key("start_s").value(e.start_s);
        json.key("end_s").value(e.end_s);
        json.key("direction").value(static_cast<long long>(e.direction));
        json.key("order").value(core::detector::defectOrderText(e.direction));
        json.key("peak_r").value(e.peakR);
        json.key("lag_ms").value(std::round(e.peakLag_s * 1e9) / 1e6);
        if (e.speed_m_per_s) json.key("speed_mm_s").value(*e.speed_m_per_s * 1e3);
        json.endObject();
    }
    json.endArray();
    core::detector::writeSitesJson(json, sites);
    if (probe) {
        json.key("probe_agreement").beginObject();
        json.key("agreeing").value(static_cast<long long>(probe->agreeing));
        json.key("compared").value(static_cast<long long>(probe->compared));
        json.endObject();
    }
    json.endObject();
    return json.str();
}

void printDetection(const QString& source, double dt_s, const DetectionOutput& output, const DetectorOptions& options)
{
    const auto [samples, lags, elapsed_s, events, sites] = output;
    QTextStream out(stdout);
    const auto& p = options.parameters;
    out << source << ": " << samples << " samples at " << QString::number(1.0 / dt_s, 'g', 6) << " Hz, " << lags
        << " lags, "
        << (p.window_s ? QStringLiteral("sliding window of %1 ms").arg(*p.window_s * 1e3)
                       : QStringLiteral("exponential weighting"))
        << '\n';
    out << "detection: " << QString::number(elapsed_s * 1e3, 'f', 1) << " ms ("
        << QString::number(static_cast<double>(samples) / elapsed_s / 1e6, 'f', 2) << " M samples/s) on "
        << kernelName(options) << ", " << threadsUsed(options)
        << (threadsUsed(options) == 1 ? " thread\n" : " threads\n");
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
            << core::detector::defectOrderText(e.direction) << QString::number(e.peakR, 'f', 3)
            << QString::number(e.peakLag_s * 1e3, 'f', 1);
        if (e.speed_m_per_s) out << QString::number(*e.speed_m_per_s * 1e3, 'f', 0);
        out << qSetFieldWidth(0) << '\n';
    }
    const auto n = sites.sites.size();
    out << n << (n == 1 ? " site" : " sites") << " (" << QString::fromStdString(sites.method) << ")"
        << (n == 0 ? "\n" : ":\n");
    for (std::size_t i = 0; i < n; ++i)
        out << "  " << i + 1 << ": " << QString::fromStdString(core::detector::siteText(sites.sites[i])) << '\n';
}

}  // namespace tactiscope::cli
