// DeviceConnector: the simulator at once, the emulator and ports through a
// handshake on a worker thread.
#include "ui/device/DeviceConnector.h"

#include "devices/DeviceDiscovery.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "ui/device/DevicePanel.h"

#include <QCoreApplication>
#include <QDir>

namespace tactiscope::ui {
namespace {

// Where the emulator puts its link: one per running Tactiscope.
QString emulatorLinkPath()
{
    return QDir::temp().filePath(QStringLiteral("tactiscope-emulator-%1").arg(QCoreApplication::applicationPid()));
}

}  // namespace

DeviceConnector::DeviceConnector(Handlers handlers, QObject* parent)
    : QObject(parent),
      m_handlers(std::move(handlers))
{
}

DeviceConnector::~DeviceConnector()
{
    cancel();
    m_connectors.clear();  // joins
}

void DeviceConnector::request(const SourceRequest& request)
{
    switch (request.kind) {
    case SourceKind::Simulator:
        connectSimulator(request.scenario);
        return;
    case SourceKind::Emulator: {
        devices::emulator::EmulatorOptions options;
        options.linkPath = emulatorLinkPath().toStdString();
        options.protocol = request.options.protocol;
        options.scenario = request.scenario;
        m_handlers.disconnect();  // the old emulator's link goes before the new one takes its path
        std::shared_ptr<devices::emulator::ProbeEmulator> emulator;
        try {
            emulator = std::make_shared<devices::emulator::ProbeEmulator>(options);
            emulator->start();
        } catch (const std::exception& e) {
            m_handlers.failed({tr("Cannot start the emulator"), tr("The probe emulator could not start."),
                               QString::fromStdString(e.what()),
                               tr("Its link goes into %1: check that the folder is writable.").arg(QDir::tempPath())});
            return;
        }
        // The opener owns the emulator, so it lives exactly as long as the
        // connection to it (and goes after the port, which is closed first).
        const devices::DiscoveredDevice link{devices::DeviceBus::Serial, options.linkPath, {}, options.linkPath};
        open(tr("emulator (%1)").arg(QString::fromStdString(request.scenario)),
             [emulator, open = devices::deviceOpener(link, request.baud, request.options)] { return open(); });
        return;
    }
    case SourceKind::Port:
        open(QString::fromStdString(request.device.path),
             devices::deviceOpener(request.device, request.baud, request.options));
        return;
    }
}

void DeviceConnector::connectSimulator(const std::string& scenario)
{
    auto simulated = devices::simulator::makeScenario(scenario);
    auto rig = simulated->loadRig();
    m_handlers.disconnect();
    m_handlers.connected(std::make_unique<devices::simulator::SimulatorSource>(std::move(simulated)), std::move(rig));
}

void DeviceConnector::open(const QString& label, devices::ReconnectingSource::Opener opener)
{
    m_handlers.disconnect();
    const std::uint64_t attempt = ++m_attempt;
    m_connectingLabel = label;
    m_handlers.connecting(label);
    m_connectors.emplace_back([this, attempt, opener = std::move(opener)] {
        auto result = std::make_shared<std::unique_ptr<devices::BlockSource>>();
        QString error;
        try {
            *result = std::make_unique<devices::ReconnectingSource>(opener);
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, attempt, result, error] { finish(attempt, std::move(*result), error); }, Qt::QueuedConnection);
    });
}

void DeviceConnector::cancel()
{
    ++m_attempt;
    m_connectingLabel.reset();
}

void DeviceConnector::finish(std::uint64_t attempt, std::unique_ptr<devices::BlockSource> source, const QString& error)
{
    if (attempt != m_attempt) return;  // cancelled, or superseded by another connect
    const QString label = m_connectingLabel.value_or(QString());
    m_connectingLabel.reset();
    if (source) {
        m_handlers.connected(std::move(source), nullptr);
        return;
    }
    m_handlers.failed({tr("Cannot connect"), tr("Tactiscope could not connect to %1.").arg(label), error,
                       tr("Check that the probe is plugged in and powered, the port and its protocol and baud rate, "
                          "then connect again."),
                       QStringLiteral("connectErrorBox")});
}

}  // namespace tactiscope::ui
