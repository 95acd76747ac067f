// MainWindow: wiring of the live session, the plots, menus and status bar.
#include "ui/MainWindow.h"

#include "core/LiveBuffer.h"
#include "core/capacitive/LiveCapacitive.h"
#include "core/compliance/LivePalpation.h"
#include "core/detector/LiveDetection.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "ui/AboutText.h"
#include "ui/ActiveProfiles.h"
#include "ui/CapacitiveView.h"
#include "ui/DesignTool.h"
#include "ui/DevicePanel.h"
#include "ui/InterruptedSessionsReport.h"
#include "ui/LivePlotWidget.h"
#include "ui/PalpationView.h"
#include "ui/PanelScanView.h"
#include "ui/RawConsole.h"
#include "ui/SensorProfileDialog.h"
#include "ui/SessionBar.h"
#include "ui/SiteGridMap.h"
#include "ui/VerdictDialog.h"
#include "ui/VocabularyText.h"
#include "ui/XYPlotWidget.h"
#include "ui/calibration/CalibrationHistory.h"
#include "ui/calibration/CapacitiveWizard.h"
#include "ui/calibration/GaugeFactorWizard.h"
#include "ui/calibration/StoredCalibrations.h"
#include "ui/review/ReviewWindow.h"
#include "ui/review/SessionBrowser.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>

#include <cmath>

namespace tactiscope::ui {
namespace {

constexpr int kStatusInterval_ms = 250;

QString defaultStorePath()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("sessions.tactiscope"));
}

LinkCounters linkCounters(const devices::AcquisitionStats& stats, const devices::BlockSource& source)
{
    LinkCounters counters;
    counters.rate_hz = stats.measuredRate_hz;
    counters.nominalRate_hz = source.nominalSampleRate_hz();
    counters.samples = stats.samples;
    counters.samplesLost = stats.samplesLost;
    switch (stats.state) {
    case devices::AcquisitionState::Idle:
        counters.state = MainWindow::tr("Idle");
        break;
    case devices::AcquisitionState::Streaming:
        counters.state = MainWindow::tr("Streaming");
        break;
    case devices::AcquisitionState::Finished:
        counters.state = MainWindow::tr("Finished");
        break;
    case devices::AcquisitionState::Failed:
        counters.state = MainWindow::tr("Failed: %1").arg(QString::fromStdString(stats.error));
        counters.healthy = false;
        break;
    }
    // A device away (unplugged) is still "streaming" to the acquisition.
    if (const auto* reconnecting = dynamic_cast<const devices::ReconnectingSource*>(&source)) {
        counters.decoder = reconnecting->decoderCounters();
        counters.reconnections = reconnecting->reconnections();
        switch (reconnecting->state()) {
        case devices::DeviceState::Lost:
            counters.state = MainWindow::tr("Device lost");
            counters.healthy = false;
            break;
        case devices::DeviceState::Reconnecting:
            counters.state = MainWindow::tr("Reconnecting…");
            counters.healthy = false;
            break;
        case devices::DeviceState::Streaming:
            break;
        }
    }
    return counters;
}

// Where the emulator puts its link: one per running Tactiscope.
QString emulatorLinkPath()
{
    return QDir::temp().filePath(QStringLiteral("tactiscope-emulator-%1").arg(QApplication::applicationPid()));
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_plot(new LivePlotWidget(this)),
      m_panelScan(new PanelScanView(this)),
      m_palpationView(new PalpationView(this)),
      m_capacitiveView(new CapacitiveView(this)),
      m_devicePanel(new DevicePanel(this))
{
    setWindowTitle(tr("Tactiscope"));
    setWindowIcon(QIcon(QStringLiteral(":/tactiscope/icons/tactiscope.svg")));
    // The traces on top, the mode's view (its lanes, readings and controls) below.
    auto* centre = new QSplitter(Qt::Vertical, this);
    centre->setObjectName(QStringLiteral("centreSplitter"));
    centre->addWidget(m_plot);
    // One mode view at a time, in one splitter pane whose height the user sets.
    m_modeViews = new QStackedWidget(this);
    m_modeViews->setObjectName(QStringLiteral("modeViews"));
    m_modeViews->addWidget(m_panelScan);
    m_modeViews->addWidget(m_palpationView);
    m_modeViews->addWidget(m_capacitiveView);
    centre->addWidget(m_modeViews);
    centre->setStretchFactor(0, 3);
    centre->setStretchFactor(1, 2);
    centre->setSizes({540, 360});
    centre->setChildrenCollapsible(false);
    setCentralWidget(centre);
    resize(1200, 720);
    m_sessionBar = new SessionBar(this);
    m_sessionBar->setObjectName(QStringLiteral("sessionBar"));
    QToolBar* sessionToolBar = addToolBar(tr("Session"));
    sessionToolBar->setObjectName(QStringLiteral("sessionToolBar"));
    sessionToolBar->setMovable(false);
    sessionToolBar->addWidget(m_sessionBar);
    connect(m_sessionBar, &SessionBar::recordClicked, this, &MainWindow::toggleRecording);
    connect(m_sessionBar, &SessionBar::modeChanged, this, &MainWindow::modeChosen);
    m_deviceDock = new QDockWidget(tr("Device"), this);
    m_deviceDock->setObjectName(QStringLiteral("deviceDock"));
    m_deviceDock->setWidget(m_devicePanel);
    m_deviceDock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
    addDockWidget(Qt::LeftDockWidgetArea, m_deviceDock);
    resizeDocks({m_deviceDock}, {290}, Qt::Horizontal);
    m_xyPlot = new XYPlotWidget(this);
    m_xyPlot->setObjectName(QStringLiteral("xyPlot"));
    m_xyDock = new QDockWidget(tr("XY plot"), this);
    m_xyDock->setObjectName(QStringLiteral("xyDock"));
    m_xyDock->setWidget(m_xyPlot);
    addDockWidget(Qt::RightDockWidgetArea, m_xyDock);
    m_xyDock->hide();  // on request (View menu): the mode views come first
    m_rawConsole = new RawConsole(this);
    m_rawConsole->setObjectName(QStringLiteral("rawConsole"));
    m_consoleDock = new QDockWidget(tr("Raw data"), this);
    m_consoleDock->setObjectName(QStringLiteral("consoleDock"));
    m_consoleDock->setWidget(m_rawConsole);
    addDockWidget(Qt::BottomDockWidgetArea, m_consoleDock);
    m_consoleDock->hide();  // for troubleshooting a probe
    connect(m_palpationView, &PalpationView::profilesRequested, this, &MainWindow::showProfiles);
    connect(m_palpationView, &PalpationView::tareRequested, this, &MainWindow::tare);
    connect(m_capacitiveView, &CapacitiveView::tareRequested, this, &MainWindow::tare);
    connect(m_capacitiveView, &CapacitiveView::profilesRequested, this, &MainWindow::showProfiles);
    connect(m_devicePanel, &DevicePanel::connectRequested, this, &MainWindow::connectRequest);
    connect(m_devicePanel, &DevicePanel::disconnectRequested, this, &MainWindow::disconnectSource);
    createMenus();
    createStatusBar();
    restoreSettings();
    m_statusTimer.setInterval(kStatusInterval_ms);
    connect(&m_statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
}

MainWindow::~MainWindow()
{
    disconnectSource();  // ends a recording, with everything kept
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    stopRecording();
    saveSettings();
    event->accept();
}

void MainWindow::restoreSettings()
{
    const QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    core::storage::SessionMetadata metadata;
    metadata.mode = core::modeFromString(settings.value(QStringLiteral("session/mode")).toString().toStdString())
                        .value_or(core::Mode::PanelScan);
    metadata.operatorName = settings.value(QStringLiteral("session/operator")).toString().toStdString();
    m_sessionBar->setMetadata(metadata);
    setStorePath(settings.value(QStringLiteral("recording/store"), defaultStorePath()).toString());
    showModeView();
}

void MainWindow::showModeView()
{
    const core::Mode mode = m_sessionBar->metadata().mode;
    QWidget* view = nullptr;
    if (m_session) {
        if (m_session->detection() && mode == core::Mode::PanelScan) view = m_panelScan;
        if (m_session->palpation() && mode == core::Mode::Palpation) view = m_palpationView;
        if (m_session->capacitive() && mode == core::Mode::Capacitive) view = m_capacitiveView;
    }
    if (view) m_modeViews->setCurrentWidget(view);
    m_modeViews->setVisible(view != nullptr);
    showModeXY(view);
}

// A mode the device cannot feed is refused here, before anything is
// recorded: the bar goes back to the session's mode and says why.
void MainWindow::modeChosen()
{
    if (m_session) {
        const core::Mode chosen = m_sessionBar->metadata().mode;
        if (const auto refusal = m_session->setMode(chosen)) {
            const QSignalBlocker quiet(m_sessionBar);
            m_sessionBar->setMode(m_session->mode());
            showProblem(
                tr("Mode not available"),
                tr("%1 cannot run on %2.").arg(modeTitle(chosen), QString::fromStdString(m_session->source().name())),
                QString::fromStdString(*refusal), QStringLiteral("modeRefusedBox"));
        }
    }
    showModeView();
}

// The XY plot the mode calls for: F_H against F_L in palpation (slope Q),
// force against tip deflection for the capacitive beam (slope k_s).
void MainWindow::showModeXY(const QWidget* view)
{
    const double rate_hz = m_session ? m_session->source().nominalSampleRate_hz() : 0.0;
    if (view == m_palpationView) {
        const DisplayUnit high{1e3, tr("mN"), tr("F_H")}, low{1e3, tr("mN"), tr("F_L")};
        m_xyPlot->setSource(m_session->palpation()->output(), 1, 0, low, high, rate_hz);
        m_xyDock->setWindowTitle(tr("XY plot: F_H against F_L (slope Q)"));
    } else if (view == m_capacitiveView) {
        const DisplayUnit deflection{1e3, tr("mm"), tr("Tip deflection")}, force{1e6, tr("µN"), tr("Force")};
        m_xyPlot->setSource(m_session->capacitive()->output(), 1, 0, deflection, force, rate_hz);
        m_xyDock->setWindowTitle(tr("XY plot: force against deflection (slope k_s)"));
    } else {
        m_xyPlot->clearSource();
        m_xyDock->setWindowTitle(tr("XY plot (palpation and capacitive modes)"));
    }
}

void MainWindow::saveSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    const auto metadata = m_sessionBar->metadata();
    settings.setValue(QStringLiteral("session/mode"), wordText(metadata.mode));
    settings.setValue(QStringLiteral("session/operator"), QString::fromStdString(metadata.operatorName));
    settings.setValue(QStringLiteral("recording/store"), m_storePath);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);

    QMenu* device = menuBar()->addMenu(tr("&Device"));
    device->addAction(tr("&Choose a device…"), QKeySequence(tr("Ctrl+K")), this, [this] {
        m_deviceDock->show();
        m_deviceDock->raise();
        m_devicePanel->setFocus();
    });
    QMenu* simulator = device->addMenu(tr("&Simulator"));
    for (const std::string& id : devices::simulator::scenarioIds()) {
        simulator->addAction(QString::fromStdString(id), this, [this, id] { connectSimulator(id); });
    }
    device->addSeparator();
    device->addAction(tr("&Disconnect"), this, &MainWindow::disconnectSource);

    QMenu* session = menuBar()->addMenu(tr("&Session"));
    session->addAction(tr("Start / stop &recording"), QKeySequence(tr("Ctrl+R")), this, &MainWindow::toggleRecording);
    session->addAction(tr("&Mark event"), QKeySequence(tr("Ctrl+M")), this, [this] { markEvent(); });
    session->addAction(tr("Mark event with a &note…"), QKeySequence(tr("Ctrl+Shift+M")), this,
                       &MainWindow::markEventWithNote);
    session->addAction(tr("&Tare"), QKeySequence(tr("Ctrl+T")), this, &MainWindow::tare);
    session->addSeparator();
    session->addAction(tr("Sensor &profiles…"), QKeySequence(tr("Ctrl+Shift+P")), this, &MainWindow::showProfiles);
    session->addAction(tr("Session &store…"), this, &MainWindow::chooseStore);
    session->addAction(tr("&Browse and review sessions…"), QKeySequence::Open, this, &MainWindow::showSessionBrowser);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_deviceDock->toggleViewAction());
    view->addAction(m_xyDock->toggleViewAction());
    view->addAction(m_consoleDock->toggleViewAction());
    view->addSeparator();
    // Pause and hold act on every plot together, so traces and lanes stay aligned.
    const auto plotToggle = [this, view](const QString& text, const QString& name, const QString& keys,
                                         const QString& tip, void (LivePlotWidget::*set)(bool)) {
        QAction* action = view->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(keys));
        action->setToolTip(tip);
        connect(action, &QAction::toggled, this, [this, set](bool on) {
            for (LivePlotWidget* plot : allPlots()) (plot->*set)(on);
        });
        return action;
    };
    QAction* pause = plotToggle(tr("&Pause display"), QStringLiteral("pauseAction"), tr("Ctrl+Space"),
                                tr("Freeze the plots to look back; acquisition and recording go on (Ctrl+Space)"),
                                &LivePlotWidget::setPaused);
    QAction* hold =
        plotToggle(tr("&Hold value scale"), QStringLiteral("holdScaleAction"), tr("Ctrl+H"),
                   tr("Stop autoscaling the value axes; drag them to adjust (Ctrl+H)"), &LivePlotWidget::setScaleHeld);
    QToolBar* display = addToolBar(tr("Display"));
    display->setObjectName(QStringLiteral("displayToolBar"));
    display->setMovable(false);
    display->setToolButtonStyle(Qt::ToolButtonTextOnly);
    display->addAction(pause);
    display->addAction(hold);
    QMenu* window = view->addMenu(tr("Time &window"));
    // One window for the traces and the mode's lanes, so they line up in time.
    auto* windows = new QActionGroup(this);
    for (const double seconds : {5.0, 10.0, 30.0, 60.0}) {
        QAction* action = window->addAction(tr("%1 s").arg(seconds));
        action->setCheckable(true);
        action->setChecked(seconds == LivePlotWidget::kDefaultWindow_s);
        windows->addAction(action);
        connect(action, &QAction::triggered, this, [this, seconds] {
            for (LivePlotWidget* plot : allPlots()) plot->setWindowLength(seconds);
            m_xyPlot->setWindowLength(seconds);
        });
    }

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->addAction(tr("Calibrate the &gauge factor…"), this, [this] { calibrate(QStringLiteral("gauge")); });
    tools->addAction(tr("Calibrate the &capacitive beam (C0, sensitivity)…"), this,
                     [this] { calibrate(QStringLiteral("capacitive")); });
    tools->addAction(tr("Calibration &history…"), this, [this] {
        auto* history = new CalibrationHistory(m_storePath, this);
        history->setAttribute(Qt::WA_DeleteOnClose);
        history->show();
    });
    tools->addSeparator();
    tools->addAction(tr("Compliance probe &design…"), this, [this] {
        auto* tool = new DesignTool(ProfileLibrary::defaultDirectory(), this);
        tool->setAttribute(Qt::WA_DeleteOnClose);
        tool->show();
    });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About Tactiscope"), this, &MainWindow::showAbout);
}

std::vector<LivePlotWidget*> MainWindow::allPlots() const
{
    return {m_plot, m_panelScan->lanes(), m_palpationView->lanes(), m_capacitiveView->lanes()};
}

void MainWindow::createStatusBar()
{
    m_deviceLabel = new QLabel(tr("No device"), this);
    m_linkLabel = new QLabel(this);
    m_recordingLabel = new QLabel(this);
    m_deviceLabel->setObjectName(QStringLiteral("deviceLabel"));
    m_linkLabel->setObjectName(QStringLiteral("linkLabel"));
    m_recordingLabel->setObjectName(QStringLiteral("recordingLabel"));
    m_deviceLabel->setContentsMargins(6, 0, 6, 0);
    statusBar()->addWidget(m_deviceLabel, 1);
    // Fixed fields on the right, each with breathing room.
    for (QLabel* label : {m_linkLabel, m_recordingLabel}) {
        label->setContentsMargins(10, 0, 10, 0);
        statusBar()->addPermanentWidget(label);
    }
}

void MainWindow::setStorePath(const QString& path)
{
    if (m_browser && path != m_storePath) m_browser->close();  // it lists the old store
    m_storePath = path;
    m_sessionBar->setStorePath(path);
}

void MainWindow::chooseStore()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Session store"), m_storePath,
                                                      tr("Tactiscope session stores (*.tactiscope);;All files (*)"),
                                                      nullptr, QFileDialog::DontConfirmOverwrite);
    if (path.isEmpty()) return;
    setStorePath(path);
    reportInterruptedSessions();
}

bool MainWindow::setMode(core::Mode mode)
{
    m_sessionBar->setMode(mode);  // modeChosen() asks the session
    return m_sessionBar->metadata().mode == mode;
}

core::Mode MainWindow::mode() const
{
    return m_sessionBar->metadata().mode;
}

bool MainWindow::isRecording() const
{
    return m_session && m_session->isRecording();
}

void MainWindow::reportInterruptedSessions()
{
    // Each interrupted session is reported once, on the first start after it.
    QSettings settings;
    const QString key =
        QStringLiteral("recording/interruptedReported/%1").arg(QFileInfo(m_storePath).absoluteFilePath());
    const auto sessions = interruptedSessionsAfter(m_storePath, settings.value(key, 0).toLongLong());
    if (sessions.empty()) return;
    settings.setValue(key, static_cast<qlonglong>(sessions.back()));
    showInterruptedSessionsReport(this, m_storePath, sessions,
                                  [this](const std::vector<std::int64_t>& ids) { reviewSessions(ids); });
}

SessionBrowser* MainWindow::showSessionBrowser()
{
    if (!m_browser) {
        m_browser = new SessionBrowser(m_storePath, this);
        m_browser->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_browser, &SessionBrowser::openSessions, this, &MainWindow::reviewSessions);
        // A deleted session's review window has nothing left to show.
        connect(m_browser, &SessionBrowser::sessionsDeleted, this, [this](const std::vector<std::int64_t>& ids) {
            for (ReviewWindow* window : findChildren<ReviewWindow*>())
                if (std::ranges::find(ids, window->sessionId()) != ids.end()) window->close();
        });
    }
    m_browser->show();
    m_browser->raise();
    m_browser->activateWindow();
    return m_browser;
}

void MainWindow::reviewSessions(const std::vector<std::int64_t>& sessions)
{
    QStringList problems;
    for (const std::int64_t id : sessions) {
        const auto windows = findChildren<ReviewWindow*>();
        const auto open = std::ranges::find(windows, id, &ReviewWindow::sessionId);
        ReviewWindow* window = open != windows.end() ? *open : nullptr;
        QString error;
        if (!window) window = ReviewWindow::open(m_storePath, id, this, error);
        if (!window) {
            problems << error;
            continue;
        }
        window->show();
        window->raise();
    }
    if (!problems.isEmpty())
        showProblem(tr("Review"), tr("Not every session could be opened."), problems.join(QLatin1Char('\n')));
}

void MainWindow::toggleRecording()
{
    if (isRecording())
        stopRecording();
    else
        startRecording();
}

bool MainWindow::startRecording()
{
    if (isRecording()) return true;
    if (!m_session) {
        statusBar()->showMessage(tr("Connect a device to record."), 5000);
        return false;
    }
    if (const auto error = m_session->startRecording(m_sessionBar->metadata())) {
        showProblem(tr("Cannot record"), tr("Recording could not start."), QString::fromStdString(*error));
        return false;
    }
    m_sessionBar->setRecording(true);
    lockProfiles();
    updateRecording();
    return true;
}

void MainWindow::stopRecording()
{
    if (!isRecording()) return;
    if (const auto summary = m_session->stopRecording()) recordingEnded(*summary);
}

void MainWindow::recordingEnded(const devices::session::RecordingSummary& summary)
{
    m_sessionBar->setRecording(false);
    if (m_browser) m_browser->reload();
    lockProfiles();
    m_sessionBar->setRecordEnabled(m_session != nullptr);
    const QLocale locale;
    m_recordingLabel->setStyleSheet(QString());
    m_recordingLabel->setText(tr("Session %1 saved: %2 samples per channel")
                                  .arg(summary.session)
                                  .arg(locale.toString(static_cast<qulonglong>(summary.stats.samplesWritten))));
    if (!summary.stats.error.empty())
        showProblem(tr("Recording stopped"), tr("Recording stopped early."),
                    QString::fromStdString(summary.stats.error));
    else if (summary.verdict)
        askVerdict(summary.session, summary.end_s, static_cast<int>(summary.defects), *summary.verdict);
}

// The panel's automatic verdict is stored with the session; the operator
// keeps it or overrides it, with a note that goes into the session as an
// annotation at its end, without being held up.
void MainWindow::askVerdict(std::int64_t session, double end_s, int defects, core::Verdict verdict)
{
    const std::string store = m_storePath.toStdString();
    const auto save = [this, store, session](core::Verdict chosen) {
        try {
            core::storage::SessionStore(store).setVerdict(session, chosen);
            statusBar()->showMessage(tr("Session %1: verdict \"%2\"").arg(session).arg(wordText(chosen)), 5000);
        } catch (const core::storage::StorageError& e) {
            showProblem(tr("Verdict not saved"), tr("The verdict could not be saved."),
                        QString::fromStdString(e.what()));
        }
    };
    auto* dialog = new VerdictDialog(defects, verdict, this);
    const std::string author = m_sessionBar->metadata().operatorName;
    connect(dialog, &VerdictDialog::decided, this,
            [this, save, store, session, end_s, author, verdict](core::Verdict chosen, const QString& note) {
                if (chosen != verdict) save(chosen);
                if (note.isEmpty()) return;
                core::storage::Annotation annotation;
                annotation.time_s = end_s;
                annotation.author = author;
                annotation.text = tr("Verdict \"%1\": %2").arg(wordText(chosen), note).toStdString();
                try {
                    core::storage::SessionStore(store).addAnnotation(session, annotation);
                } catch (const core::storage::StorageError& e) {
                    showProblem(tr("Note not saved"), tr("The verdict's note could not be saved."),
                                QString::fromStdString(e.what()));
                }
            });
    dialog->show();
}

SensorProfileDialog* MainWindow::showProfiles()
{
    if (!m_profileDialog) {
        m_profileDialog = new SensorProfileDialog(ProfileLibrary::defaultDirectory(), this);
        connect(m_profileDialog, &SensorProfileDialog::activeProfileChanged, this, &MainWindow::applyProfile);
        lockProfiles();
    }
    if (!m_profileDialog->hasUnsavedChanges()) m_profileDialog->setMode(wordText(m_sessionBar->metadata().mode));
    m_profileDialog->show();
    m_profileDialog->raise();
    m_profileDialog->activateWindow();
    return m_profileDialog;
}

// A session keeps the sensor it started with, so its readings and its stored
// profile agree.
void MainWindow::lockProfiles()
{
    if (m_profileDialog)
        m_profileDialog->setLocked(isRecording(), tr("fixed while recording: a session keeps one sensor"));
}

void MainWindow::applyProfile(const QString& modeName)
{
    const auto mode = core::modeFromString(modeName.toStdString());
    if (!m_session || !mode) return;  // the next connection reads it
    ActiveProfile active = activeProfile(modeName);
    if (!active.error.isEmpty())
        showProblem(tr("Bad profile"),
                    tr("The %1 profile could not be used; the paper's sensor is used instead.").arg(modeName),
                    active.error);
    if (const auto refusal = m_session->setProfile(*mode, std::move(active.profile))) {
        showProblem(tr("Bad profile"), tr("The %1 probe was not changed.").arg(modeName),
                    QString::fromStdString(*refusal));
        return;
    }
    showMode(*mode);
    if (*mode == core::Mode::Palpation && m_session->palpation())
        statusBar()->showMessage(tr("New probe profile: keep the probe lifted while it tares"), 5000);
    if (*mode == core::Mode::Capacitive && m_session->capacitive())
        statusBar()->showMessage(tr("New beam profile: the baseline C0 is re-taken"), 5000);
}

// A mode's view on the session's processor, with the probe's name and the
// calibrations it reads through.
void MainWindow::showMode(core::Mode mode)
{
    const double rate_hz = m_session ? m_session->source().nominalSampleRate_hz() : 0.0;
    const auto* profile = m_session ? m_session->profile(mode) : nullptr;
    const QString probe = profile ? QString::fromStdString(core::sensors::profileName(*profile)) : QString();
    QStringList calibrations;
    if (m_session)
        for (const auto& stored : m_session->calibrations(mode))
            calibrations << tr("%1 on %2 by %3")
                                .arg(QString::fromStdString(stored.record.sensorName),
                                     QString::fromStdString(stored.record.timestampUtc),
                                     QString::fromStdString(stored.record.operatorName));
    switch (mode) {
    case core::Mode::PanelScan:
        m_panelScan->setDetection(m_session ? m_session->detection() : nullptr, rate_hz);
        break;
    case core::Mode::Palpation:
        m_palpationView->setPalpation(m_session ? m_session->palpation() : nullptr, rate_hz, probe,
                                      calibrations.join(QStringLiteral(", ")));
        break;
    case core::Mode::Capacitive:
        m_capacitiveView->setCapacitive(m_session ? m_session->capacitive() : nullptr, rate_hz, probe,
                                        calibrations.isEmpty()
                                            ? tr("none — the beam model (uncalibrated); drift tracking off")
                                            : calibrations.join(QStringLiteral(", ")));
        break;
    }
    showModeView();
}

// Calibrating needs the live signal and must not change the calibration of
// a session being recorded.
void MainWindow::calibrate(const QString& which)
{
    if (!m_session) {
        statusBar()->showMessage(tr("Connect the probe to calibrate (or the simulator's calibration rig)."), 6000);
        m_deviceDock->show();
        return;
    }
    if (isRecording()) {
        statusBar()->showMessage(tr("Stop recording first: a session keeps the calibration it started with."), 6000);
        return;
    }
    CalibrationContext context{m_session->buffer(),
                               m_session->source().channels(),
                               m_session->source().nominalSampleRate_hz(),
                               m_loadRig,
                               m_storePath,
                               QString::fromStdString(m_sessionBar->metadata().operatorName),
                               ProfileLibrary::defaultDirectory()};
    QWizard* wizard = nullptr;
    if (which == QLatin1String("gauge")) {
        auto* gauge = new GaugeFactorWizard(std::move(context), this);
        connect(gauge, &GaugeFactorWizard::calibrationStored, this, [this](std::int64_t, const QString& sensor) {
            if (m_session) m_session->reloadCalibrations(core::Mode::Palpation);
            showMode(core::Mode::Palpation);
            statusBar()->showMessage(tr("Gauge factor of %1 stored; the palpation view reads through it.").arg(sensor),
                                     8000);
        });
        wizard = gauge;
    } else if (which == QLatin1String("capacitive")) {
        auto* capacitive = new CapacitiveWizard(std::move(context), this);
        connect(capacitive, &CapacitiveWizard::calibrationStored, this, [this](std::int64_t, const QString& sensor) {
            if (m_session) m_session->reloadCalibrations(core::Mode::Capacitive);
            showMode(core::Mode::Capacitive);
            statusBar()->showMessage(tr("Calibration of %1 stored; the capacitive view reads through it.").arg(sensor),
                                     8000);
        });
        wizard = capacitive;
    }
    if (!wizard) return;
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
}

void MainWindow::tare()
{
    if (!m_session) {
        statusBar()->showMessage(tr("Connect a probe to tare it."), 5000);
        return;
    }
    if (const auto refusal = m_session->tare()) {
        statusBar()->showMessage(tr("Not tared: %1").arg(QString::fromStdString(*refusal)), 8000);
        return;
    }
    statusBar()->showMessage(tr("Tared: the last half second is the new zero"), 4000);
}

void MainWindow::markEvent(const QString& note)
{
    if (!isRecording()) {
        statusBar()->showMessage(tr("Markers go into a recording: start one first (Ctrl+R)."), 5000);
        return;
    }
    addMarker(m_session->sessionTime_s(), note);
}

// The marker's time is the key press; typing the note does not delay it, and
// the recording goes on meanwhile.
void MainWindow::markEventWithNote()
{
    if (!isRecording()) {
        markEvent();  // says why not
        return;
    }
    const double time_s = m_session->sessionTime_s();
    const std::int64_t session = m_session->sessionId();
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName(QStringLiteral("markerNoteDialog"));
    dialog->setWindowTitle(tr("Marker"));
    dialog->setLabelText(tr("Note for the marker at %1 s:").arg(QLocale().toString(time_s, 'f', 2)));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QInputDialog::textValueSelected, this, [this, time_s, session](const QString& note) {
        if (isRecording() && m_session->sessionId() == session)
            addMarker(time_s, note);
        else
            showProblem(tr("Marker not stored"), tr("The recording ended before the note was entered."), note);
    });
    dialog->open();
}

void MainWindow::addMarker(double time_s, const QString& note)
{
    m_session->addMarker(time_s, note.toStdString());
    statusBar()->showMessage(tr("Marker at %1 s").arg(QLocale().toString(time_s, 'f', 2)), 4000);
}

void MainWindow::updateRecording()
{
    if (!isRecording()) return;
    const auto stats = m_session->recorderStats();
    const double elapsed_s = m_session->sessionTime_s();
    m_sessionBar->setElapsed(elapsed_s);
    const QLocale locale;
    QString text = tr("● REC session %1: %2 samples")
                       .arg(m_session->sessionId())
                       .arg(locale.toString(static_cast<qulonglong>(stats.samplesWritten)));
    if (stats.samplesDropped > 0)
        text += tr(", %1 lost").arg(locale.toString(static_cast<qulonglong>(stats.samplesDropped)));
    m_recordingLabel->setText(text);
    m_recordingLabel->setStyleSheet(QStringLiteral("color: #c62828; font-weight: 600;"));
}

// Problems are shown in a window that does not block: acquisition and
// recording go on, and the operator closes it when convenient.
void MainWindow::showProblem(const QString& title, const QString& text, const QString& detail,
                             const QString& objectName)
{
    qWarning("%s: %s", qPrintable(text), qPrintable(detail));
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setObjectName(objectName);
    box->setInformativeText(detail);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
}

void MainWindow::connectSimulator(const std::string& scenario)
{
    auto simulated = devices::simulator::makeScenario(scenario);
    auto rig = simulated->loadRig();
    connectSource(std::make_unique<devices::simulator::SimulatorSource>(std::move(simulated)));
    m_loadRig = std::move(rig);  // after connectSource, which forgets the old device's rig
}

void MainWindow::connectRequest(const SourceRequest& request)
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
        disconnectSource();  // the old emulator's link goes before the new one takes its path
        std::shared_ptr<devices::emulator::ProbeEmulator> emulator;
        try {
            emulator = std::make_shared<devices::emulator::ProbeEmulator>(options);
            emulator->start();
        } catch (const std::exception& e) {
            showProblem(tr("Cannot start the emulator"), tr("The probe emulator could not start."),
                        QString::fromStdString(e.what()));
            return;
        }
        // The opener owns the emulator, so it lives exactly as long as the
        // connection to it (and goes after the port, which is closed first).
        const devices::DiscoveredDevice link{devices::DeviceBus::Serial, options.linkPath, {}, options.linkPath};
        connectDevice(tr("emulator (%1)").arg(QString::fromStdString(request.scenario)),
                      [emulator, open = devices::deviceOpener(link, request.baud, request.options)] { return open(); });
        return;
    }
    case SourceKind::Port:
        connectDevice(QString::fromStdString(request.device.path),
                      devices::deviceOpener(request.device, request.baud, request.options));
        return;
    }
}

void MainWindow::connectDevice(const QString& label, devices::ReconnectingSource::Opener opener)
{
    disconnectSource();
    const std::uint64_t attempt = ++m_connectAttempt;
    m_connectingLabel = label;
    m_deviceLabel->setText(label);
    m_linkLabel->setText(tr("Connecting…"));
    m_devicePanel->setConnecting(label);
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
    m_devicePanel->setConnected(false);
    m_devicePanel->clearCounters(tr("Connection failed"));
    m_linkLabel->setText(tr("Connection failed"));
    showProblem(tr("Cannot connect"), tr("Tactiscope could not connect to %1.").arg(label), error,
                QStringLiteral("connectErrorBox"));
}

void MainWindow::connectSource(std::unique_ptr<devices::BlockSource> source)
{
    disconnectSource();
    if (!source) return;
    devices::session::LiveSessionOptions options;
    options.storePath = m_storePath.toStdString();
    options.displaySeconds = LivePlotWidget::kMaxWindow_s + 2.0;
    for (const QString& mode : profileModes()) {
        ActiveProfile active = activeProfile(mode);
        if (!active.error.isEmpty())
            showProblem(tr("Bad profile"),
                        tr("The %1 profile could not be used; the paper's sensor is used instead.").arg(mode),
                        active.error);
        options.profiles.emplace(*core::modeFromString(mode.toStdString()), std::move(active.profile));
    }
    m_session = std::make_unique<devices::session::LiveSession>(std::move(source), std::move(options));
    for (const auto& problem : m_session->takeProblems())
        showProblem(tr("Analysis not available"), tr("Part of the analysis cannot run on this device."),
                    QString::fromStdString(problem));
    // The source's own mode wins; a source that declares none keeps the
    // bar's mode if its channels can feed it.
    const core::Mode chosen = m_sessionBar->metadata().mode;
    if (!m_session->declaredMode() && !m_session->refusalOf(chosen)) m_session->setMode(chosen);
    if (m_session->mode() != chosen) {
        const QSignalBlocker quiet(m_sessionBar);
        m_sessionBar->setMode(m_session->mode());
        statusBar()->showMessage(
            tr("Mode: %1, the mode of %2")
                .arg(modeTitle(m_session->mode()), QString::fromStdString(m_session->source().name())),
            6000);
    }
    for (const core::Mode mode : core::kModes) showMode(mode);
    const auto& device = m_session->source();
    m_plot->setSource(m_session->buffer(), device.channels(), device.nominalSampleRate_hz());
    m_session->start();

    const QString name = QString::fromStdString(device.name());
    setWindowTitle(tr("Tactiscope — %1").arg(name));
    m_deviceLabel->setText(name);
    m_devicePanel->setConnected(true, name);
    m_rawConsole->setSource(&device);
    updateStatus();
    m_statusTimer.start();
    m_sessionBar->setRecordEnabled(true);
}

void MainWindow::disconnectSource()
{
    ++m_connectAttempt;  // a connect still in its handshake is dropped when it answers
    m_connectingLabel.reset();
    stopRecording();  // the user ended the session by disconnecting
    m_statusTimer.stop();
    m_rawConsole->setSource(nullptr);  // before the source goes
    m_plot->clearSource();
    m_panelScan->setDetection(nullptr, 0.0);
    m_palpationView->setPalpation(nullptr, 0.0, QString());
    m_capacitiveView->setCapacitive(nullptr, 0.0, QString(), QString());
    m_session.reset();
    m_loadRig.reset();
    showModeView();
    setWindowTitle(tr("Tactiscope"));
    m_deviceLabel->setText(tr("No device"));
    m_linkLabel->clear();
    m_devicePanel->setConnected(false);
    m_sessionBar->setRecordEnabled(false);
}

void MainWindow::updateStatus()
{
    if (!m_session) return;
    const LinkCounters counters = linkCounters(m_session->stats(), m_session->source());
    m_devicePanel->showCounters(counters);
    QString link = counters.state;
    if (counters.rate_hz) link += tr(" · %1 Hz").arg(QLocale().toString(*counters.rate_hz, 'f', 1));
    if (counters.samplesLost > 0)
        link += tr(" · %1 lost").arg(QLocale().toString(static_cast<qulonglong>(counters.samplesLost)));
    m_linkLabel->setText(link);
    m_linkLabel->setStyleSheet(counters.healthy ? QString() : QStringLiteral("color: #c62828; font-weight: 600;"));
    // The site first: a press completed in this poll was taken there.
    m_session->setSite(m_palpationView->siteGrid()->currentSite().toStdString());
    if (const auto stopped = m_session->poll()) recordingEnded(*stopped);  // the disk stopped it
    m_panelScan->showDefects(m_session->panelDefects());
    m_palpationView->showPresses(m_session->presses());
    m_palpationView->updateReadout();
    m_capacitiveView->updateReadouts();
    updateRecording();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Tactiscope"), aboutText());
}

}  // namespace tactiscope::ui
