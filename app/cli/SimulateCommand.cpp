// The simulate subcommand.
#include "SimulateCommand.h"

#include "CliSupport.h"
#include "HumOptions.h"
#include "core/SampleBlock.h"
#include "core/storage/SessionExport.h"
#include "core/text/NumberFormat.h"
#include "devices/simulator/PalpationScenario.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>

namespace tactiscope::cli {
namespace {

constexpr double kMaxSeconds = 24.0 * 3600.0;

QString scenarioList()
{
    QStringList ids;
    for (const auto& id : devices::simulator::scenarioIds()) ids << toQString(id);
    return ids.join(QStringLiteral(", "));
}

// Streams the whole simulation into `out` as CSV: units in the header, as
// a session export writes them, and the load a calibration scenario
// applies as its last column (the researcher's log of the weights).
void writeCsv(devices::simulator::SimulatorSource& source, const devices::simulator::SimulatedScenario& scenario,
              std::ostream& out)
{
    const bool loads = scenario.appliedLoad_n(0.0).has_value();
    std::string line = "t [s]";
    for (const auto& channel : source.channels()) line += ',' + core::storage::csvHeader(channel);
    if (loads) line += ",load [N]";
    out << line << '\n';

    const double rate_hz = source.nominalSampleRate_hz();
    core::SampleBlock block;
    while (source.readBlock(block, std::chrono::milliseconds(0)) == devices::ReadStatus::Block) {
        for (std::size_t i = 0; i < block.sampleCount(); ++i) {
            line.clear();
            // i/rate rather than t0 + i·Δt: "0.174", not "0.17400000000000002".
            core::text::appendShortest(line, static_cast<double>(block.firstSampleIndex() + i) / rate_hz);
            for (std::size_t c = 0; c < block.channelCount(); ++c) {
                line += ',';
                core::text::appendShortest(line, block.value(c, i));
            }
            if (loads) {
                line += ',';
                const double t_s = static_cast<double>(block.firstSampleIndex() + i) / rate_hz;
                core::text::appendShortest(line, *scenario.appliedLoad_n(t_s));
            }
            line += '\n';
            out << line;
        }
    }
}

}  // namespace

int runSimulate(const QStringList& arguments)
{
    const QString name = QStringLiteral("simulate");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Write a simulated recording as CSV, units in the header (t [s], high [count], …); a scenario that "
        "places loads adds the load it applies at each sample, load [N]."));
    const QCommandLineOption scenarioOption(
        QStringLiteral("scenario"),
        QStringLiteral("Scenario: %1 (default %2).")
            .arg(scenarioList(), QString::fromStdString(devices::simulator::kPanelScanScenario)),
        QStringLiteral("ID"), QString::fromStdString(devices::simulator::kPanelScanScenario));
    const QCommandLineOption secondsOption(QStringLiteral("seconds"), QStringLiteral("Length in seconds (default 10)."),
                                           QStringLiteral("S"), QStringLiteral("10"));
    const QCommandLineOption seedOption(QStringLiteral("seed"), QStringLiteral("Noise seed (default 1)."),
                                        QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption outputOption(
        QStringLiteral("output"), QStringLiteral("Write to FILE instead of standard output."), QStringLiteral("FILE"));
    const QCommandLineOption stiffnessOption(
        QStringLiteral("object-stiffness"),
        QStringLiteral("palpation: the phantom's stiffness in N/m (default 117, the paper's)."), QStringLiteral("K"));
    const QCommandLineOption depthsOption(
        QStringLiteral("depths-mm"), QStringLiteral("palpation: the press depths in mm, cycled (default 2,4,6,8)."),
        QStringLiteral("LIST"));
    parser.addOptions({scenarioOption, secondsOption, seedOption, outputOption, stiffnessOption, depthsOption});
    addHumOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument %1").arg(quoted(parser.positionalArguments().front())),
                          usage);

    bool ok = false;
    const double seconds = parser.value(secondsOption).toDouble(&ok);
    if (!ok || !std::isfinite(seconds) || seconds <= 0.0 || seconds > kMaxSeconds)
        return usageError(QStringLiteral("--seconds must be a number of seconds in (0, 86400], got %1")
                              .arg(quoted(parser.value(secondsOption))),
                          usage);
    const qulonglong seed = parser.value(seedOption).toULongLong(&ok);
    if (!ok)
        return usageError(
            QStringLiteral("--seed must be a non-negative integer, got %1").arg(quoted(parser.value(seedOption))),
            usage);
    const QString scenarioId = parser.value(scenarioOption);
    auto scenario = devices::simulator::makeScenario(scenarioId.toStdString(), seed);
    if (!scenario)
        return usageError(QStringLiteral("unknown scenario '%1' (known: %2)").arg(scenarioId, scenarioList()), usage);
    if (parser.isSet(stiffnessOption) || parser.isSet(depthsOption)) {
        if (scenarioId.toStdString() != devices::simulator::kPalpationScenario)
            return usageError(QStringLiteral("--object-stiffness and --depths-mm are for --scenario palpation"), usage);
        devices::simulator::PalpationParameters phantom;
        phantom.seed = seed;
        if (parser.isSet(stiffnessOption)) {
            phantom.objectStiffness_n_per_m = parser.value(stiffnessOption).toDouble(&ok);
            if (!ok || !std::isfinite(phantom.objectStiffness_n_per_m) || phantom.objectStiffness_n_per_m <= 0.0)
                return usageError(QStringLiteral("--object-stiffness must be a positive number of N/m, got %1")
                                      .arg(quoted(parser.value(stiffnessOption))),
                                  usage);
        }
        if (parser.isSet(depthsOption)) {
            phantom.pressDepths_m.clear();
            for (const QString& depth : parser.value(depthsOption).split(QLatin1Char(','))) {
                const double mm = depth.trimmed().toDouble(&ok);
                if (!ok || !std::isfinite(mm) || mm <= 0.0 || mm > 50.0)
                    return usageError(
                        QStringLiteral("--depths-mm must list depths in (0, 50] mm, got %1").arg(quoted(depth)), usage);
                phantom.pressDepths_m.push_back(mm * 1e-3);
            }
        }
        scenario = std::make_unique<devices::simulator::PalpationScenario>(phantom);
    }

    QString humError;
    const auto hum = parseHumOptions(parser, humError);
    if (!hum) return usageError(humError, usage);
    if (hum->any()) scenario = std::make_unique<devices::simulator::HummedScenario>(std::move(scenario), *hum);
    const devices::simulator::SimulatedScenario& simulated = *scenario;  // owned by the source from here
    devices::simulator::SimulatorSource source(std::move(scenario),
                                               {devices::simulator::Pacing::AsFastAsPossible, 500, seconds});

    if (!parser.isSet(outputOption)) {
        writeCsv(source, simulated, std::cout);
        std::cout.flush();
        if (!std::cout) {
            printError(QStringLiteral("cannot write to standard output"));
            return kExitFailure;
        }
        return kExitOk;
    }
    const QString path = parser.value(outputOption);
    std::ofstream file(path.toStdString(), std::ios::binary | std::ios::trunc);
    if (!file) {
        printError(QStringLiteral("cannot create '%1': %2").arg(path, QString::fromLocal8Bit(std::strerror(errno))));
        return kExitFailure;
    }
    writeCsv(source, simulated, file);
    file.close();
    if (!file) {
        printError(QStringLiteral("cannot write '%1': %2").arg(path, QString::fromLocal8Bit(std::strerror(errno))));
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
