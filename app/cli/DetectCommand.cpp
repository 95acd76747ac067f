// The detect subcommand: options → DetectorParameters, CSV in, CSV/JSON out.
#include "DetectCommand.h"

#include "CliSupport.h"
#include "DetectorOptions.h"
#include "core/UnitScale.h"
#include "core/detector/CsvDetection.h"
#include "core/detector/HumRisk.h"
#include "core/detector/ProbeScanFiles.h"
#include "core/dsp/FilterSettings.h"
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"
#include "core/storage/Database.h"
#include "core/storage/SafeOutput.h"
#include "core/text/CountText.h"
#include "core/text/JsonWriter.h"
#include "core/text/NumberFormat.h"

#include <QTextStream>

#include <algorithm>
#include <iostream>

namespace tactiscope::cli {
namespace {

using core::detector::DefectEvent;
using core::detector::DetectorParameters;
using core::detector::ProbeOutput;

struct DetectOptions {
    QString input;
    QString output;
    QString probeInput;      // write the emulated probe's input instead of detecting
    QString probeDecisions;  // the rows from the emulated probe's decisions instead of detecting
    std::vector<std::string> columns{"t", "a", "b"};
    std::optional<std::string> position;  // the rig's position column: sites from it
    std::optional<double> notch_hz;       // a mains notch on every cantilever first
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
    if (parser.isSet(QStringLiteral("position"))) {
        options.position = parser.value(QStringLiteral("position")).trimmed().toStdString();
        if (options.position->empty()) return QStringLiteral("--position needs the position column's name");
    }
    const QString engine = parser.value(QStringLiteral("engine"));
    if (engine == QStringLiteral("probe"))
        options.detector.engine = core::detector::DetectorEngine::Probe;
    else if (engine != QStringLiteral("workstation"))
        return QStringLiteral("--engine is workstation or probe, not %1").arg(quoted(engine));
    if (const auto error = readDetectorOptions(parser, options.detector)) return error;
    if (options.detector.engine == core::detector::DetectorEngine::Probe && options.detector.threads > 1)
        return QStringLiteral("--threads is the workstation's: the probe's kernel runs on one");
    if (parser.isSet(QStringLiteral("notch"))) {
        QString error;
        options.notch_hz = parseMainsFrequency(QStringLiteral("notch"), parser.value(QStringLiteral("notch")), error);
        if (!options.notch_hz) return error;
    }
    options.probeInput = parser.value(QStringLiteral("probe-input"));
    options.probeDecisions = parser.value(QStringLiteral("probe-decisions"));
    if (!options.probeInput.isEmpty() && (!options.output.isEmpty() || !options.probeDecisions.isEmpty()))
        return QStringLiteral("--probe-input writes the emulated probe's input, nothing else");
    if (options.notch_hz && (!options.probeInput.isEmpty() || !options.probeDecisions.isEmpty()))
        return QStringLiteral(
            "--notch goes with detecting: --probe-input and --probe-decisions write the scan as it is");
    if (options.position && (!options.probeInput.isEmpty() || !options.probeDecisions.isEmpty()))
        return QStringLiteral("--position goes with detecting: --probe-input and --probe-decisions write files");
    if (!options.probeDecisions.isEmpty() && options.output.isEmpty())
        return QStringLiteral("--probe-decisions goes with --output OUT.csv, the rows it makes");
    return std::nullopt;
}

// Refuses a --position column that holds no length ("t [s]", "a
// [strain]"); a length in another unit than m ("x [mm]") the column
// reader refuses, as it reads SI only.
void checkPositionColumn(const std::string& path, const std::string& column)
{
    const std::vector<std::string> headers = core::io::CsvReader(path).header();
    for (const std::string& header : headers) {
        const auto [name, unit] = core::io::splitColumnHeader(header);
        const auto physical = core::physicalUnit(unit);
        if ((header == column || name == column) && !unit.empty() &&
            (!physical || physical->kind != core::ChannelKind::Position))
            throw core::detector::CsvDetectionError(
                "'" + path + "': --position " + column + ": the column " + core::io::quotedForMessage(header) +
                " holds no length; the position is the probe's place along its stroke, in m");
    }
}

// A length column of the file that detect was not told of: the rig's
// position, most likely, which would place the sites exactly.
std::optional<std::string> unusedLengthColumn(const std::string& path, const std::vector<std::string>& used)
{
    const std::vector<std::string> headers = core::io::CsvReader(path).header();
    for (const std::string& header : headers) {
        const auto [name, unit] = core::io::splitColumnHeader(header);
        if (unit == "m" && std::ranges::find(used, name) == used.end() && std::ranges::find(used, header) == used.end())
            return name;
    }
    return std::nullopt;
}

// Runs `work` over a scan: what the scan or a file throws becomes its
// message and exit code (bad input 2, a file that cannot be written 1).
template <typename Work>
int scanExitCode(Work&& work)
{
    try {
        work();
    } catch (const core::io::CsvError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    } catch (const core::detector::CsvDetectionError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    } catch (const std::invalid_argument& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    return kExitOk;
}

// The emulated probe's files (qemu-detect.sh), the scan read as detect
// reads it: a scan detect refuses is refused here in the same words.
int emulatedProbeFiles(const DetectOptions& options)
{
    const std::string input = options.input.toStdString();
    const bool packs = !options.probeInput.isEmpty();
    const QString written = packs ? options.probeInput : options.output;
    return scanExitCode([&] {
        std::vector<std::string> inputs{input};
        if (!packs) inputs.push_back(options.probeDecisions.toStdString());
        core::storage::refuseOverwriting(written.toStdString(), inputs);
        std::size_t samples = 0;
        core::storage::writeAtomically(written.toStdString(), [&](std::ostream& out) {
            samples = packs ? core::detector::writeProbeInput(input, options.columns, options.detector.parameters, out)
                            : core::detector::writeProbeDecisionRows(input, options.columns,
                                                                     options.probeDecisions.toStdString(), out);
        });
        QTextStream(stdout) << written << ": " << samples
                            << (packs ? " samples for the emulated probe\n"
                                      : " rows of the emulated probe's decisions\n");
    });
}

// "Between t = 1.2 and 1.26 s (line 122), …": where the first few gaps
// are, so that the user can look at the file there.
std::string gapsText(const std::vector<core::detector::TimeGap>& gaps)
{
    constexpr std::size_t kNamed = 5;
    std::string text;
    for (std::size_t i = 0; i < std::min(gaps.size(), kNamed); ++i)
        text += std::string(i == 0 ? "Between t = " : ", between t = ") + core::text::formatShortest(gaps[i].before_s) +
                " and " + core::text::formatShortest(gaps[i].after_s) + " s (line " +
                std::to_string(gaps[i].lineAfter) + ")";
    if (gaps.size() > kNamed) text += " and " + std::to_string(gaps.size() - kNamed) + " more";
    return text + ".";
}

}  // namespace

int runDetect(const QStringList& arguments)
{
    const QString name = QStringLiteral("detect");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Run the surface-deflection detector (partial correlation, seed 000) over a CSV recording.\n"
                       "INPUT.csv has a header and columns t,a,b (t in seconds, a and b dimensionless strain).\n"
                       "The summary lists the events and the defect sites they make. Without --spacing-mm the "
                       "events have no scan speed and their sites no place by phase (analyze and a live "
                       "recording take the prototype's 15 mm); --position places them by the rig's encoder."));
    parser.addPositionalArgument(QStringLiteral("INPUT.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("columns"), QStringLiteral("Time and cantilever columns, in probe order (default t,a,b)."),
         QStringLiteral("T,A,B")},
        {QStringLiteral("output"), QStringLiteral("Write t,out,rab,rba,lag_ab_ms,lag_ba_ms per sample to OUT.csv."),
         QStringLiteral("OUT.csv")},
        {QStringLiteral("position"),
         QStringLiteral("The rig's position column (an encoder along the stroke, in m): each crossing is placed "
                        "where it says, on its scale, not by its phase from the stroke's centre (docs/detector.md)."),
         QStringLiteral("X")},
        {QStringLiteral("notch"),
         QStringLiteral(
             "Run every cantilever through a mains notch first (50 or 60 Hz and harmonics, causal, as "
             "live): a press line's hum otherwise correlates the gauges at every period (docs/detector.md)."),
         QStringLiteral("50|60")},
        {QStringLiteral("engine"),
         QStringLiteral("workstation (default: double precision) or probe (the probe's own single-precision "
                        "kernel, firmware/probe-detector, exponential form, one thread)."),
         QStringLiteral("ENGINE"), QStringLiteral("workstation")},
        {QStringLiteral("probe-input"),
         QStringLiteral("Instead of detecting, write the scan and the detector's settings as an emulated probe reads "
                        "them (firmware/probe-detector/scan_format.h) to FILE."),
         QStringLiteral("FILE")},
        {QStringLiteral("probe-decisions"),
         QStringLiteral("Instead of detecting, write --output's rows from an emulated probe's decisions FILE "
                        "(scan_format.h) for this scan."),
         QStringLiteral("FILE")},
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

    if (!options.probeInput.isEmpty() || !options.probeDecisions.isEmpty()) return emulatedProbeFiles(options);

    core::detector::CsvDetection result;
    core::detector::StretchSettings settings{options.detector.parameters, options.detector.hold_s,
                                             options.detector.spacing_m,  options.detector.threads,
                                             options.detector.engine,     {}};
    if (options.notch_hz) {
        core::dsp::FilterSettings notch;
        notch.notch_hz = options.notch_hz;
        settings.filters = {notch};
    }
    const std::string input = options.input.toStdString();
    std::optional<std::string> unusedLength;
    double positionSpan_m = 0.0;
    const int exit = scanExitCode([&] {
        if (options.position)
            checkPositionColumn(input, *options.position);
        else
            unusedLength = unusedLengthColumn(input, options.columns);
        if (options.output.isEmpty()) {
            result = core::detector::detectCsv(input, options.columns, settings);
        } else {
            // Rows written as they come: the output never waits in memory.
            core::storage::writeAtomically(options.output.toStdString(), [&](std::ostream& out) {
                out << core::detector::kSampleRowsHeader;
                std::string rows;
                result = core::detector::detectCsv(input, options.columns, settings,
                                                   [&](std::span<const ProbeOutput> outputs, double interval_s) {
                                                       core::detector::appendSampleRows(rows, outputs, interval_s);
                                                       out << rows;
                                                   });
            });
        }
        if (options.position)
            positionSpan_m = core::detector::stampCsvPositions(input, options.columns.front(), *options.position,
                                                               result.interval_s, result.events);
    });
    if (exit != kExitOk) return exit;
    if (positionSpan_m > core::detector::kMaxStroke_m)
        std::cerr << "note: the column '" << *options.position << "' spans " << positionSpan_m
                  << " m, more than a panel probe's stroke (" << core::detector::kMaxStroke_m
                  << " m): is it in m? Its sites are placed as it says\n";
    if (!result.gaps.empty()) {
        std::cerr << "note: the time column skips whole intervals: "
                  << core::text::countText(result.gaps.size(), "gap", "gaps") << " (" << result.samplesMissing
                  << " samples missing, as an export of a session that lost samples leaves them out): the detector "
                     "restarted after each gap, never bridging one. "
                  << gapsText(result.gaps) << '\n';
    }
    std::vector<std::string> cantilevers(options.columns.begin() + 1, options.columns.end());
    if (const auto risk = core::detector::detectorHumRisk(cantilevers, result.cantileverHealth, 1.0 / result.interval_s,
                                                          options.notch_hz))
        std::cerr << "note: " << core::detector::humRiskText(*risk, options.notch_hz, 1.0, {}) << "; --notch "
                  << core::text::formatShortest(risk->mains_hz) << " takes it out\n";
    if (unusedLength)
        std::cerr << "note: the column '" << *unusedLength
                  << "' is a length: if it is the rig's position along the stroke, --position " << *unusedLength
                  << " places each site where it says\n";
    const auto sites = core::detector::scanSites(result.events, options.position.has_value());
    const DetectionOutput output{result.samples, result.lags, result.detectorSeconds, result.events, sites};
    if (options.detector.json)
        std::cout << eventsJson(output, options.detector) << '\n';
    else
        printDetection(options.input, result.interval_s, output, options.detector);
    return kExitOk;
}

}  // namespace tactiscope::cli
