// The shunt-check subcommand: options, the device in the live pipeline (as
// record runs it), a ShuntCheckRun driven to its end, the line, and the
// record in the calibration history.
#include "ShuntCheckCommand.h"

#include "CliSupport.h"
#include "RecordOutput.h"
#include "core/storage/SessionStore.h"
#include "core/text/UncertaintyFormat.h"
#include "devices/ReconnectingSource.h"
#include "devices/session/LivePipeline.h"
#include "devices/session/ShuntCheckRun.h"

#include <QLocale>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace tactiscope::cli {
namespace {

std::optional<core::straingauge::BridgeType> parseBridge(const QString& text)
{
    if (text == QStringLiteral("quarter")) return core::straingauge::BridgeType::Quarter;
    if (text == QStringLiteral("half")) return core::straingauge::BridgeType::HalfBending;
    if (text == QStringLiteral("full")) return core::straingauge::BridgeType::FullBending;
    return std::nullopt;
}

// "+5.00", "-0.56", "0.00" (no sign on what rounds to nothing).
QString deviationText(double deviation)
{
    const double percent = std::round(deviation * 1e4) / 100.0;
    return (percent > 0.0 ? QStringLiteral("+") : QString()) +
           QLocale::c().toString(percent == 0.0 ? 0.0 : percent, 'f', 2);
}

}  // namespace

int runShuntCheck(const QStringList& arguments)
{
    const QString name = QStringLiteral("shunt-check");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Check a strain channel's bridge with its probe's shunt (TSP/1 command 6): the mean with the shunt off and\n"
        "on, one second each, against the step the shunt, the gauge and the bridge say it must be:\n"
        "quarter y/GF, half y/((2 + y)GF), full y/((4 + 2y)GF), with y = -Rg/(Rg + Rs)."));
    parser.addOptions({
        {QStringLiteral("port"), QStringLiteral("Serial port or link to it (required)."), QStringLiteral("PATH")},
        {QStringLiteral("channel"), QStringLiteral("The strain channel, by name (required)."), QStringLiteral("NAME")},
        {QStringLiteral("bridge"), QStringLiteral("quarter (default), half or full (bending)."),
         QStringLiteral("TYPE")},
        {QStringLiteral("gauge-ohms"), QStringLiteral("The gauges' resistance (default 350)."), QStringLiteral("OHM")},
        {QStringLiteral("shunt-ohms"), QStringLiteral("The shunt's resistance (default 100000)."),
         QStringLiteral("OHM")},
        {QStringLiteral("gauge-factor"), QStringLiteral("The gauges' factor, from their data sheet (default 2)."),
         QStringLiteral("GF")},
        {QStringLiteral("tolerance"), QStringLiteral("The deviation that still passes, in percent (default 1)."),
         QStringLiteral("PERCENT")},
        {QStringLiteral("db"), QStringLiteral("Keep the result in this store's calibration history."),
         QStringLiteral("FILE")},
        {QStringLiteral("operator"), QStringLiteral("Who checks."), QStringLiteral("NAME")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument %1").arg(quoted(parser.positionalArguments().front())),
                          usage);
    if (!parser.isSet(QStringLiteral("port"))) return usageError(QStringLiteral("--port PATH is required"), usage);
    if (!parser.isSet(QStringLiteral("channel")))
        return usageError(QStringLiteral("--channel NAME is required"), usage);
    devices::session::ShuntCheckSettings settings;
    if (parser.isSet(QStringLiteral("bridge"))) {
        const auto bridge = parseBridge(parser.value(QStringLiteral("bridge")));
        if (!bridge) return usageError(QStringLiteral("--bridge must be quarter, half or full"), usage);
        settings.bridge = *bridge;
    }
    double tolerance_percent = settings.tolerance * 100.0;
    for (const auto& [option, range, into] :
         {std::tuple{"gauge-ohms", core::kGaugeOhmsRange, &settings.gauge_ohm},
          std::tuple{"shunt-ohms", core::kShuntOhmsRange, &settings.shunt_ohm},
          std::tuple{"gauge-factor", core::kGaugeFactorRange, &settings.gaugeFactor},
          std::tuple{"tolerance", core::kShuntToleranceRange, &tolerance_percent}}) {
        QString error;
        const auto value = numberInRange(parser, option, range, *into, error);
        if (!value) return usageError(error, usage);
        *into = *value;
    }
    settings.tolerance = tolerance_percent / 100.0;

    std::unique_ptr<devices::BlockSource> source;
    try {
        source = devices::serialOpener(parser.value(QStringLiteral("port")).toStdString(), {}, 921600, {})();
    } catch (const std::exception& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    const auto channels = source->channels();
    const std::string channelName = parser.value(QStringLiteral("channel")).toStdString();
    const auto found = std::ranges::find(channels, channelName, &core::ChannelDescriptor::name);
    if (found == channels.end()) {
        printError(QStringLiteral("the probe has no channel %1").arg(quoted(toQString(channelName))));
        return kExitUsage;
    }
    settings.channel = static_cast<std::size_t>(found - channels.begin());
    const std::string sensor = source->identity().serial + " " + channelName;

    // The one live pipeline, as record runs it: what the link notices is
    // told as it is while recording.
    const std::string storePath = parser.value(QStringLiteral("db")).toStdString();
    devices::session::LivePipeline pipeline(storePath);
    if (const auto refusal = pipeline.add(std::move(source), {})) {
        printError(QString::fromStdString(*refusal));
        return kExitFailure;
    }
    pipeline.start();
    RecordOutput output(storePath, pipeline, std::nullopt, false);
    devices::session::ShuntCheckRun run(pipeline.device(0), settings);
    installStopSignals();
    while (!run.advance()) {
        if (stopRequested()) {
            printError(QStringLiteral("stopped before the check was done; the shunt is switched off"));
            return kExitFailure;
        }
        output.tell(pipeline.poll());
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const auto& result = *run.result();
    if (!result.refusal.empty()) {
        printError(QString::fromStdString(result.refusal));
        return kExitFailure;
    }
    // The expected step to the measured one's decimals, side by side.
    const int decimals = std::max(1, core::text::uncertaintyDecimals(result.measured.uncertainty * 1e6));
    const auto& check = result.check;
    QTextStream(stdout) << "Shunt check " << toQString(channelName) << ": expected "
                        << QLocale::c().toString(run.expected() * 1e6, 'f', decimals) << " µε, measured "
                        << toQString(core::text::valueWithUncertainty(result.measured.step * 1e6,
                                                                      result.measured.uncertainty * 1e6, "µε"))
                        << ", deviation " << deviationText(check.deviation) << " % (tolerance "
                        << QLocale::c().toString(tolerance_percent) << " %): " << (check.passed ? "PASS" : "FAIL")
                        << Qt::endl;
    if (parser.isSet(QStringLiteral("db"))) {
        try {
            core::storage::SessionStore store(storePath);
            store.addCalibration(run.record(sensor, parser.value(QStringLiteral("operator")).toStdString()));
        } catch (const core::storage::StorageError& e) {
            printError(QStringLiteral("the result was not kept: %1").arg(QString::fromStdString(e.what())));
            return kExitFailure;
        }
    }
    return check.passed ? kExitOk : kExitFailure;
}

}  // namespace tactiscope::cli
