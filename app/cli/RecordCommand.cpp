// The record subcommand: options, the device with reconnection, the
// recorder, and the summary.
#include "RecordCommand.h"

#include "CliSupport.h"
#include "core/storage/Recorder.h"
#include "core/storage/RecorderLock.h"
#include "devices/Acquisition.h"
#include "devices/ReconnectingSource.h"
#include "devices/transport/SerialPorts.h"

#include <QLocale>
#include <QTextStream>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>
#include <unistd.h>

namespace tactiscope::cli {
namespace {

constexpr int kDefaultBaud = 921600;
constexpr double kQueueSeconds = 30.0;  // the recorder's memory bound, in time

// The USB serial number of the port behind `path` (a link is followed), so a
// replugged probe is found again even under another name.
std::string usbSerialOf(const std::string& path)
{
    std::error_code error;
    const auto resolved = std::filesystem::canonical(path, error);
    if (error) return {};
    for (const auto& port : devices::transport::listSerialPorts()) {
        if (port.path == resolved.string()) return port.usbSerialNumber;
    }
    return {};
}

}  // namespace

int runRecord(const QStringList& arguments)
{
    const QString name = QStringLiteral("record");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Record a probe on a serial port into a session store, until --seconds or Ctrl-C.\n"
                       "An unplugged probe is waited for and the gap is marked in the recording."));
    parser.addOptions({
        {QStringLiteral("port"), QStringLiteral("Serial port or link to it (required)."), QStringLiteral("PATH")},
        {QStringLiteral("protocol"), QStringLiteral("binary (TSP/1, default) or text."), QStringLiteral("binary|text")},
        {QStringLiteral("baud"), QStringLiteral("Baud rate (default %1).").arg(kDefaultBaud), QStringLiteral("N")},
        {QStringLiteral("rate"),
         QStringLiteral("Sample rate in Hz: text, the rate of the lines (else estimated); binary, asked of the "
                        "device."),
         QStringLiteral("HZ")},
        {QStringLiteral("seconds"), QStringLiteral("Record this long (default: until Ctrl-C)."), QStringLiteral("S")},
        {QStringLiteral("db"), QStringLiteral("Session store to record into (required; created if missing)."),
         QStringLiteral("FILE")},
        {QStringLiteral("subject"), QStringLiteral("Panel or phantom id."), QStringLiteral("ID")},
        {QStringLiteral("operator"), QStringLiteral("Who records."), QStringLiteral("NAME")},
        {QStringLiteral("mode"), QStringLiteral("panel-scan (default), palpation or capacitive."),
         QStringLiteral("MODE")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()), usage);
    if (!parser.isSet(QStringLiteral("port"))) return usageError(QStringLiteral("--port PATH is required"), usage);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);

    const std::string port = parser.value(QStringLiteral("port")).toStdString();
    const std::string db = parser.value(QStringLiteral("db")).toStdString();
    devices::PortSourceOptions options;
    const auto protocol = parseWireProtocol(parser.value(QStringLiteral("protocol")));
    if (!protocol) return usageError(QStringLiteral("--protocol must be binary or text"), usage);
    options.protocol = *protocol;
    int baud = kDefaultBaud;
    if (parser.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        baud = parser.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || baud <= 0) return usageError(QStringLiteral("--baud must be a positive whole number"), usage);
    }
    if (parser.isSet(QStringLiteral("rate"))) {
        const auto rate = parseNumber(parser.value(QStringLiteral("rate")));
        if (!rate || *rate <= 0.0) return usageError(QStringLiteral("--rate must be a positive number of Hz"), usage);
        (options.protocol == devices::WireProtocol::Text ? options.textRate_hz : options.requestRate_hz) = rate;
    }
    std::optional<double> seconds;
    if (parser.isSet(QStringLiteral("seconds"))) {
        seconds = parseNumber(parser.value(QStringLiteral("seconds")));
        if (!seconds || *seconds <= 0.0)
            return usageError(QStringLiteral("--seconds must be a positive number"), usage);
    }
    core::storage::SessionMetadata metadata;
    metadata.mode = parser.isSet(QStringLiteral("mode")) ? parser.value(QStringLiteral("mode")).toStdString()
                                                         : std::string("panel-scan");
    if (metadata.mode != "panel-scan" && metadata.mode != "palpation" && metadata.mode != "capacitive")
        return usageError(QStringLiteral("--mode must be panel-scan, palpation or capacitive"), usage);
    metadata.subject = parser.value(QStringLiteral("subject")).toStdString();
    metadata.operatorName = parser.value(QStringLiteral("operator")).toStdString();

    // A store we may not write (not ours, newer, being recorded into) is bad
    // input: say so before touching the device.
    try {
        core::storage::SessionStore check(db);
        core::storage::RecorderLock::acquire(db);  // released at once; taken again by the recorder
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    // The first connection is made here, to read the device's identity;
    // the reconnecting source takes it over and reopens it after an unplug.
    const auto reopen = devices::serialOpener(port, usbSerialOf(port), baud, options);
    std::unique_ptr<devices::BlockSource> first;
    try {
        auto source = reopen();
        if (const auto* portSource = dynamic_cast<const devices::PortSource*>(source.get())) {
            if (const auto info = portSource->deviceInfo()) {
                metadata.deviceModel = info->vendor + " " + info->model;
                metadata.deviceSerial = info->serialNumber;
                metadata.deviceFirmware = info->firmwareVersion;
            }
        }
        first = std::move(source);
    } catch (const std::exception& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    const double rate_hz = first->nominalSampleRate_hz();
    if (options.requestRate_hz && std::abs(rate_hz - *options.requestRate_hz) > 1e-6 * *options.requestRate_hz)
        printError(QStringLiteral("the device streams at %1 Hz, not the %2 Hz asked for; recording at %1 Hz")
                       .arg(rate_hz)
                       .arg(*options.requestRate_hz));
    const auto channels = first->channels();
    auto handover = std::make_shared<std::unique_ptr<devices::BlockSource>>(std::move(first));
    auto source = std::make_unique<devices::ReconnectingSource>(
        [handover, reopen] { return *handover ? std::move(*handover) : reopen(); });

    std::shared_ptr<core::storage::Recorder> recorder;
    try {
        recorder = std::make_shared<core::storage::Recorder>(
            db, metadata, channels, rate_hz, static_cast<std::uint64_t>(std::ceil(kQueueSeconds * rate_hz)));
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }
    const auto* device = source.get();
    devices::Acquisition acquisition(std::move(source));
    acquisition.addSink(recorder);
    installStopSignals();
    acquisition.start();

    const bool progress = ::isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    auto nextProgress = start + std::chrono::seconds(5);
    QTextStream err(stderr);
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const auto now = std::chrono::steady_clock::now();
        const auto state = acquisition.stats().state;
        if (stopRequested() || state == devices::AcquisitionState::Finished ||
            state == devices::AcquisitionState::Failed ||
            (seconds && std::chrono::duration<double>(now - start).count() >= *seconds))
            break;
        if (!recorder->stats().error.empty()) break;
        if (progress && now >= nextProgress) {
            nextProgress += std::chrono::seconds(5);
            err << "recording… " << std::llround(std::chrono::duration<double>(now - start).count()) << " s, "
                << acquisition.stats().samples << " samples per channel\r" << Qt::flush;
        }
    }
    acquisition.stop();
    const auto acquired = acquisition.stats();
    const auto counters = device->decoderCounters();
    const auto stored = recorder->finish(core::storage::SessionStatus::Complete);
    if (progress) err << '\n';

    QTextStream(stdout) << "Recorded session " << recorder->sessionId() << ": " << stored.samplesWritten
                        << " samples per channel, " << acquired.samplesLost + stored.samplesDropped << " lost, "
                        << counters.crcErrors << " CRC errors (" << channels.size() << " channels at "
                        << QLocale::c().toString(rate_hz) << " Hz, into " << QString::fromStdString(db) << ")\n";
    if (!stored.error.empty()) {
        printError(QString::fromStdString(stored.error));
        return kExitFailure;
    }
    if (acquired.state == devices::AcquisitionState::Failed) {
        printError(QString::fromStdString(acquired.error));
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
