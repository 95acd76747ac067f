// MainWindow: wiring of acquisition, live plot, menus and status bar.
#include "ui/MainWindow.h"

#include "core/LiveBuffer.h"
#include "core/Version.h"
#include "devices/Acquisition.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "ui/ConnectDialog.h"
#include "ui/LivePlotWidget.h"

#include <QActionGroup>
#include <QApplication>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <cmath>

namespace tactiscope::ui {
namespace {

constexpr int kStatusInterval_ms = 250;

QString stateText(const devices::AcquisitionStats& stats, const devices::BlockSource& source)
{
    // A device away (unplugged) is still "streaming" to the acquisition.
    if (const auto* reconnecting = dynamic_cast<const devices::ReconnectingSource*>(&source)) {
        switch (reconnecting->state()) {
        case devices::DeviceState::Lost:
            return MainWindow::tr("Device lost");
        case devices::DeviceState::Reconnecting:
            return MainWindow::tr("Reconnecting…");
        case devices::DeviceState::Streaming:
            break;
        }
    }
    switch (stats.state) {
    case devices::AcquisitionState::Idle:
        return MainWindow::tr("Idle");
    case devices::AcquisitionState::Streaming:
        return MainWindow::tr("Streaming");
    case devices::AcquisitionState::Finished:
        return MainWindow::tr("Finished");
    case devices::AcquisitionState::Failed:
        return MainWindow::tr("Failed: %1").arg(QString::fromStdString(stats.error));
    }
    return {};
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_plot(new LivePlotWidget(this))
{
    setWindowTitle(tr("Tactiscope"));
    setWindowIcon(QIcon(QStringLiteral(":/tactiscope/icons/tactiscope.svg")));
    setCentralWidget(m_plot);
    resize(1200, 720);
    createMenus();
    createStatusBar();
    m_statusTimer.setInterval(kStatusInterval_ms);
    connect(&m_statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
}

MainWindow::~MainWindow()
{
    disconnectSource();
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);

    QMenu* device = menuBar()->addMenu(tr("&Device"));
    device->addAction(tr("&Connect to device…"), QKeySequence(tr("Ctrl+K")), this, &MainWindow::showConnectDialog);
    QMenu* simulator = device->addMenu(tr("&Simulator"));
    for (const std::string& id : devices::simulator::scenarioIds()) {
        simulator->addAction(QString::fromStdString(id), this, [this, id] {
            connectSource(std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(id)));
        });
    }
    device->addSeparator();
    device->addAction(tr("&Disconnect"), this, &MainWindow::disconnectSource);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QMenu* window = view->addMenu(tr("Time &window"));
    auto* windows = new QActionGroup(this);
    for (const double seconds : {5.0, 10.0, 30.0, 60.0}) {
        QAction* action = window->addAction(tr("%1 s").arg(seconds));
        action->setCheckable(true);
        action->setChecked(seconds == LivePlotWidget::kDefaultWindow_s);
        windows->addAction(action);
        connect(action, &QAction::triggered, this, [this, seconds] { m_plot->setWindowLength(seconds); });
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About Tactiscope"), this, &MainWindow::showAbout);
}

void MainWindow::createStatusBar()
{
    m_deviceLabel = new QLabel(tr("No device"), this);
    m_stateLabel = new QLabel(this);
    m_rateLabel = new QLabel(this);
    m_samplesLabel = new QLabel(this);
    m_deviceLabel->setObjectName(QStringLiteral("deviceLabel"));
    m_stateLabel->setObjectName(QStringLiteral("stateLabel"));
    m_rateLabel->setObjectName(QStringLiteral("rateLabel"));
    m_samplesLabel->setObjectName(QStringLiteral("samplesLabel"));
    statusBar()->addWidget(m_deviceLabel, 1);
    // Fixed fields on the right, each with breathing room and a divider.
    for (QLabel* label : {m_stateLabel, m_rateLabel, m_samplesLabel}) {
        label->setContentsMargins(10, 0, 10, 0);
        label->setFrameShape(QFrame::StyledPanel);
        statusBar()->addPermanentWidget(label);
    }
    m_deviceLabel->setContentsMargins(6, 0, 6, 0);
}

void MainWindow::showConnectDialog()
{
    ConnectDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted) return;
    const ConnectRequest request = dialog.request();
    connectDevice(QString::fromStdString(request.device.path),
                  devices::deviceOpener(request.device, request.baud, request.options));
}

void MainWindow::connectDevice(const QString& label, devices::ReconnectingSource::Opener opener)
{
    disconnectSource();
    const std::uint64_t attempt = ++m_connectAttempt;
    m_connectingLabel = label;
    m_deviceLabel->setText(label);
    m_stateLabel->setText(tr("Connecting…"));
    m_connectors.emplace_back([this, attempt, opener = std::move(opener)] {
        auto result = std::make_shared<std::unique_ptr<devices::BlockSource>>();
        QString error;
        try {
            *result = std::make_unique<devices::ReconnectingSource>(opener);
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, attempt, result, error] { finishConnecting(attempt, std::move(*result), error); },
            Qt::QueuedConnection);
    });
}

void MainWindow::finishConnecting(std::uint64_t attempt, std::unique_ptr<devices::BlockSource> source,
                                  const QString& error)
{
    if (attempt != m_connectAttempt) return;  // cancelled, or superseded by another connect
    const QString label = m_connectingLabel.value_or(QString());
    m_connectingLabel.reset();
    if (source) {
        connectSource(std::move(source));
        return;
    }
    m_stateLabel->setText(tr("Connection failed"));
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot connect"),
                                tr("Tactiscope could not connect to %1.").arg(label), QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("connectErrorBox"));
    box->setInformativeText(error);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::connectSource(std::unique_ptr<devices::BlockSource> source)
{
    disconnectSource();
    if (!source) return;
    const auto channels = source->channels();
    const double rate_hz = source->nominalSampleRate_hz();
    // Two seconds of headroom: the display reads 40 times a second, so only a
    // GUI stalled that long loses display samples (never recorded ones).
    auto buffer =
        std::make_shared<core::LiveBuffer>(channels.size(), static_cast<std::size_t>(std::ceil(2.0 * rate_hz)) + 1);
    m_acquisition = std::make_unique<devices::Acquisition>(std::move(source));
    m_acquisition->addSink(buffer);
    m_plot->setSource(buffer, channels, rate_hz);
    m_acquisition->start();

    const QString name = QString::fromStdString(m_acquisition->source().name());
    setWindowTitle(tr("Tactiscope — %1").arg(name));
    m_deviceLabel->setText(name);
    updateStatus();
    m_statusTimer.start();
}

void MainWindow::disconnectSource()
{
    ++m_connectAttempt;  // a connect still in its handshake is dropped when it answers
    m_connectingLabel.reset();
    m_statusTimer.stop();
    if (m_acquisition) m_acquisition->stop();
    m_plot->clearSource();
    m_acquisition.reset();
    setWindowTitle(tr("Tactiscope"));
    m_deviceLabel->setText(tr("No device"));
    m_stateLabel->clear();
    m_rateLabel->clear();
    m_samplesLabel->clear();
}

void MainWindow::updateStatus()
{
    if (!m_acquisition) return;
    const devices::AcquisitionStats stats = m_acquisition->stats();
    const QLocale locale;
    m_stateLabel->setText(stateText(stats, m_acquisition->source()));
    const double nominal_hz = m_acquisition->source().nominalSampleRate_hz();
    m_rateLabel->setText(stats.measuredRate_hz
                             ? tr("%1 Hz (nominal %2 Hz)")
                                   .arg(locale.toString(*stats.measuredRate_hz, 'f', 1), locale.toString(nominal_hz))
                             : tr("measuring rate… (nominal %1 Hz)").arg(locale.toString(nominal_hz)));
    QString samples = tr("%1 samples").arg(locale.toString(static_cast<qulonglong>(stats.samples)));
    if (stats.samplesLost > 0)
        samples += tr(", %1 lost").arg(locale.toString(static_cast<qulonglong>(stats.samplesLost)));
    m_samplesLabel->setText(samples);
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Tactiscope"),
                       tr("<h3>Tactiscope %1</h3>"
                          "<p>An inspection workstation for cantilever tactile sensors.</p>"
                          "<p>It implements three published sensors:</p><ul>"
                          "<li>a surface deflection detector with a viscous-capsule shear-strain probe,</li>"
                          "<li>compliance detection with two cantilevers of different stiffness,</li>"
                          "<li>a capacitive uniform-strength beam for µN forces.</li></ul>")
                           .arg(QString::fromUtf8(core::versionString())));
}

}  // namespace tactiscope::ui
