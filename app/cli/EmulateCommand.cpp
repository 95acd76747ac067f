// The emulate subcommand: options, signals and the summary.
#include "EmulateCommand.h"

#include "CliSupport.h"
#include "HumOptions.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/simulator/ScenarioCatalog.h"

#include <QTextStream>

#include <cmath>
#include <thread>
#include <tuple>

namespace tactiscope::cli {

int runEmulate(const QStringList& arguments)
{
    const QString name = QStringLiteral("emulate");
    QStringList scenarios;
    for (const auto& id : devices::simulator::scenarioIds()) scenarios << toQString(id);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Emulate a probe behind a pseudo-terminal: PATH becomes a link to it, to open like a serial port.\n"
        "Runs until --seconds have been streamed, or Ctrl-C."));
    parser.addOptions({
        {QStringLiteral("link"), QStringLiteral("Path of the link to create (required)."), QStringLiteral("PATH")},
        {QStringLiteral("protocol"), QStringLiteral("binary (TSP/1, default) or text."), QStringLiteral("binary|text")},
        {QStringLiteral("scenario"),
         QStringLiteral("%1 (default panel-scan).").arg(scenarios.join(QStringLiteral(", "))), QStringLiteral("ID")},
        {QStringLiteral("rate"), QStringLiteral("Sample rate in Hz (default: the scenario's)."), QStringLiteral("HZ")},
        {QStringLiteral("channels"), QStringLiteral("Number of channels (repeats the scenario's)."),
         QStringLiteral("N")},
        {QStringLiteral("seconds"), QStringLiteral("Stream this long after start, then hang up."), QStringLiteral("S")},
        {QStringLiteral("garbage"), QStringLiteral("Fraction of frames with injected garbage, 0 to 1."),
         QStringLiteral("RATE")},
        {QStringLiteral("seed"), QStringLiteral("Noise seed (default 1)."), QStringLiteral("N")},
        {QStringLiteral("samples-per-frame"),
         QStringLiteral("Samples per channel in each TSP/1 frame or text burst, 1 to 1000 (default 10)."),
         QStringLiteral("N")},
        {QStringLiteral("info-rate"),
         QStringLiteral("The rate its INFO frame claims, in Hz (default: the true rate; another is a lie)."),
         QStringLiteral("HZ")},
        {QStringLiteral("clock-rate"),
         QStringLiteral("The rate its clock stamps frames at, in Hz (default: the true rate; another is a clock "
                        "that lies with --info-rate)."),
         QStringLiteral("HZ")},
        {QStringLiteral("drift-ppm"),
         QStringLiteral("Its crystal's error against the host's: +80 runs its clock, and its sampling, 80 ppm slow "
                        "(default 0; within ±1000)."),
         QStringLiteral("PPM")},
        {QStringLiteral("clock-offset"),
         QStringLiteral("Its clock's reading at the first sample, in seconds (default 0; 0 to 4000)."),
         QStringLiteral("S")},
        {QStringLiteral("mark-at"),
         QStringLiteral("Mark this instant of the host's steady clock (CLOCK_MONOTONIC, seconds): the first channel "
                        "ramps by ±0.001 over 10 ms either side of it (2.5 of its own sample periods when slower "
                        "than 250 Hz). Two emulators marking one instant are one event to align."),
         QStringLiteral("S")},
        {QStringLiteral("sweep-at"),
         QStringLiteral("Begin a calibration sweep at this instant of the host's steady clock (seconds): the rig of "
                        "the capacitive-calibration or load-cell scenario pushes 0 → 1.47 mN (150 mgf) over 20 s and "
                        "back. A beam and a load cell emulated with one instant feel one force."),
         QStringLiteral("S")},
        {QStringLiteral("fault"),
         QStringLiteral("Misbehave as broken firmware (TSP/1): restart@S (silent 0.5 s, then sequence and clock "
                        "from 0), sequence-jump@S (one frame's sequence +30000), frozen-sequence, or "
                        "wrong-decisions (with --probe-detector: a detector that names every direction the wrong "
                        "way round)."),
         QStringLiteral("FAULT")},
        {QStringLiteral("no-shunt"),
         QStringLiteral("An older probe: it answers nothing to the shunt command (TSP/1 command 6). Otherwise each "
                        "strain channel's quarter bridge (350 ohm gauges, GF 2) can switch a 100 kohm shunt.")},
        {QStringLiteral("probe-detector"),
         QStringLiteral("The probe runs the surface-deflection detector itself (firmware/probe-detector) and sends "
                        "its decisions as channels out, rab and rba of kind decision (panel-scan, TSP/1).")},
    });
    addHumOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument %1").arg(quoted(parser.positionalArguments().front())),
                          usage);
    if (!parser.isSet(QStringLiteral("link"))) return usageError(QStringLiteral("--link PATH is required"), usage);

    devices::emulator::EmulatorOptions options;
    options.linkPath = parser.value(QStringLiteral("link")).toStdString();
    const auto protocol = parseWireProtocol(parser.value(QStringLiteral("protocol")));
    if (!protocol) return usageError(QStringLiteral("--protocol must be binary or text"), usage);
    options.protocol = *protocol;
    if (parser.isSet(QStringLiteral("scenario")))
        options.scenario = parser.value(QStringLiteral("scenario")).toStdString();
    const auto positive = [&](const char* key, bool integer) -> std::optional<double> {
        const auto value = parseNumber(parser.value(QString::fromLatin1(key)));
        if (!value || *value <= 0.0 || (integer && *value != std::floor(*value))) return std::nullopt;
        return value;
    };
    for (const auto& [option, into] :
         {std::pair{"rate", &options.rate_hz}, std::pair{"clock-rate", &options.clockRate_hz},
          std::pair{"info-rate", &options.infoRate_hz}})
        if (parser.isSet(QLatin1String(option))) {
            QString error;
            *into = numberInRange(parser, option, core::kSampleRateRange, 0.0, error);
            if (!*into) return usageError(error, usage);
        }
    if (parser.isSet(QStringLiteral("channels"))) {
        const auto channels = positive("channels", true);
        if (!channels || *channels > 64)
            return usageError(QStringLiteral("--channels must be a whole number from 1 to 64"), usage);
        options.channels = static_cast<std::size_t>(*channels);
    }
    if (parser.isSet(QStringLiteral("seconds"))) {
        options.seconds = positive("seconds", false);
        if (!options.seconds) return usageError(QStringLiteral("--seconds must be a positive number"), usage);
    }
    if (parser.isSet(QStringLiteral("garbage"))) {
        const auto garbage = parseNumber(parser.value(QStringLiteral("garbage")));
        if (!garbage || *garbage < 0.0 || *garbage > 1.0)
            return usageError(QStringLiteral("--garbage must lie between 0 and 1"), usage);
        options.garbageRate = *garbage;
    }
    if (parser.isSet(QStringLiteral("samples-per-frame"))) {
        const auto samples = positive("samples-per-frame", true);
        if (!samples || *samples > 1000)
            return usageError(QStringLiteral("--samples-per-frame must be a whole number from 1 to 1000"), usage);
        options.samplesPerFrame = static_cast<std::size_t>(*samples);
    }
    {
        QString humError;
        const auto hum = parseHumOptions(parser, humError);
        if (!hum) return usageError(humError, usage);
        options.hum = *hum;
    }
    if (parser.isSet(QStringLiteral("seed"))) {
        bool ok = false;
        options.seed = parser.value(QStringLiteral("seed")).toULongLong(&ok);
        if (!ok) return usageError(QStringLiteral("--seed must be a non-negative integer"), usage);
    }

    if (parser.isSet(QStringLiteral("drift-ppm"))) {
        const auto ppm = parseNumber(parser.value(QStringLiteral("drift-ppm")));
        if (!ppm || std::abs(*ppm) > 1000.0)
            return usageError(QStringLiteral("--drift-ppm must be a number of ppm within ±1000"), usage);
        options.clockDrift = *ppm * 1e-6;
    }
    if (parser.isSet(QStringLiteral("clock-offset"))) {
        // The 32-bit microsecond clock wraps at 4295 s.
        const auto offset = parseNumber(parser.value(QStringLiteral("clock-offset")));
        if (!offset || *offset < 0.0 || *offset > 4000.0)
            return usageError(QStringLiteral("--clock-offset must be a number of seconds from 0 to 4000"), usage);
        options.clockOffset_s = *offset;
    }
    if (parser.isSet(QStringLiteral("mark-at"))) {
        const auto at = parseNumber(parser.value(QStringLiteral("mark-at")));
        if (!at || *at < 0.0) return usageError(QStringLiteral("--mark-at must be a number of seconds"), usage);
        options.markAt_s = *at;
    }
    if (parser.isSet(QStringLiteral("sweep-at"))) {
        const auto at = parseNumber(parser.value(QStringLiteral("sweep-at")));
        if (!at || *at < 0.0) return usageError(QStringLiteral("--sweep-at must be a number of seconds"), usage);
        options.sweepAt_s = *at;
    }
    if (parser.isSet(QStringLiteral("fault"))) {
        const auto fault = devices::emulator::parseFault(parser.value(QStringLiteral("fault")).toStdString());
        if (!fault)
            return usageError(
                QStringLiteral("--fault must be restart@S, sequence-jump@S, frozen-sequence or wrong-decisions"),
                usage);
        std::tie(options.fault, options.faultAt_s) = *fault;
    }
    options.probeDetector = parser.isSet(QStringLiteral("probe-detector"));
    options.shunt = !parser.isSet(QStringLiteral("no-shunt"));

    std::unique_ptr<devices::emulator::ProbeEmulator> emulator;
    try {
        emulator = std::make_unique<devices::emulator::ProbeEmulator>(options);
    } catch (const std::invalid_argument& e) {
        return usageError(QString::fromStdString(e.what()), usage);
    } catch (const std::exception& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    installStopSignals();
    QTextStream out(stdout);
    out << "Emulating " << QString::fromStdString(options.scenario) << " ("
        << (options.protocol == devices::WireProtocol::Text ? "text" : "TSP/1 binary") << ") at "
        << QString::fromStdString(options.linkPath) << " -> " << QString::fromStdString(emulator->ptyPath())
        << ". Ctrl-C to stop." << Qt::endl;
    emulator->start();
    while (!stopRequested() && !emulator->finished()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    emulator->stop();
    const auto s = emulator->stats();
    out << "Sent " << s.framesSent << " frames (" << s.samplesSent << " intact samples per channel), "
        << s.corruptedFrames << " corrupted, " << s.garbageBursts << " garbage bursts, " << s.droppedFrames
        << " dropped with nobody reading, " << s.commands << " commands received." << Qt::endl;
    return kExitOk;
}

}  // namespace tactiscope::cli
