// MainWindow: the frame, the menus, the settings, and the reactions that
// need a dialog; the live widgets watch the station themselves.
#include "ui/MainWindow.h"

#include "core/modes/ModeDefinition.h"
#include "core/storage/SessionStore.h"
#include "core/storage/StoreWorker.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "ui/calibration/CalibrationWizards.h"
#include "ui/central/CentralStoreLink.h"
#include "ui/common/AboutText.h"
#include "ui/common/ElidedTextTips.h"
#include "ui/common/HelpWindows.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/VocabularyText.h"
#include "ui/device/DevicePanel.h"
#include "ui/device/OtherDevices.h"
#include "ui/device/RawConsole.h"
#include "ui/live/HandsFreeControl.h"
#include "ui/live/LiveMarkers.h"
#include "ui/live/LiveStation.h"
#include "ui/live/LiveTraces.h"
#include "ui/live/ModeChoice.h"
#include "ui/live/ModeViews.h"
#include "ui/live/QuitQuestion.h"
#include "ui/live/RecordingEndReport.h"
#include "ui/live/RecordingPolicy.h"
#include "ui/live/SessionBar.h"
#include "ui/live/StatusLine.h"
#include "ui/live/WatchBanner.h"
#include "ui/modes/LiveModeView.h"
#include "ui/modes/ModeUi.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/plot/PlotControls.h"
#include "ui/plot/XYPlotWidget.h"
#include "ui/profiles/LiveProfiles.h"
#include "ui/profiles/ProfileLibrary.h"
#include "ui/review/ReviewActions.h"
#include "ui/review/ReviewWindows.h"
#include "ui/review/SessionBrowser.h"
#include "ui/signal/LiveHealth.h"
#include "ui/signal/LiveSpectrum.h"
#include "ui/signal/SignalControl.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QIcon>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

QString defaultStorePath()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("sessions.tactiscope"));
}

QDockWidget* addDock(QMainWindow* window, const QString& title, const QString& name, QWidget* widget,
                     Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, window);
    dock->setObjectName(name);
    dock->setWidget(widget);
    window->addDockWidget(area, dock);
    return dock;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_station(new LiveStation(this)),
      m_plot(new LivePlotWidget(this)),
      m_modeViews(new ModeViews(this)),
      m_devicePanel(new DevicePanel(this)),
      m_review(new ReviewWindows(this))
{
    m_plot->setObjectName(QStringLiteral("tracesPlot"));
    ElidedTextTips::install();  // every cut cell and combo of every window says its whole text
    setWindowTitle(tr("Tactiscope"));
    setWindowIcon(QIcon(QStringLiteral(":/tactiscope/icons/tactiscope.svg")));
    buildFrame();
    watchStation();
    createMenus();
    restoreSettings();
    // The keyboard starts on the traces, where a stray key does nothing: not
    // in the detector's threshold (the first spin box in the tab order), nor
    // in a text field that would take Ctrl+K and Ctrl+H for itself.
    m_plot->setFocusPolicy(Qt::StrongFocus);
    m_plot->setFocus();
}

MainWindow::~MainWindow()
{
    m_station->disconnectDevices();  // ends a recording, with everything kept
}

void MainWindow::buildFrame()
{
    // The traces on top, the mode's view (its lanes, readings and controls)
    // below, half and half: on a 768-pixel screen the mode's view needs the
    // room as much as the traces.
    // The filtered and math channels between them, when the device has any.
    auto* centre = new QSplitter(Qt::Vertical, this);
    centre->setObjectName(QStringLiteral("centreSplitter"));
    m_signal = new SignalControl(*m_station, this);
    centre->addWidget(m_plot);
    centre->addWidget(m_signal->panel());
    centre->addWidget(m_modeViews);
    centre->setStretchFactor(0, 1);
    centre->setStretchFactor(1, 1);
    centre->setStretchFactor(2, 1);
    centre->setSizes({400, 250, 400});
    centre->setChildrenCollapsible(false);
    // The trigger's state and the alarms over the traces, shown only when they have something to say.
    auto* central = new QWidget(this);
    auto* centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->setSpacing(0);
    m_watchBanner = new WatchBanner(central);
    m_watchBanner->setObjectName(QStringLiteral("watchBanner"));
    centralLayout->addWidget(m_watchBanner);
    centralLayout->addWidget(centre, 1);
    setCentralWidget(central);
    // Fits a 1366×768 screen (less its panel) and any larger one at first start.
    resize(QSize(1340, 720).boundedTo(QGuiApplication::primaryScreen()->availableSize()));
    m_sessionBar = new SessionBar(this);
    m_sessionBar->setObjectName(QStringLiteral("sessionBar"));
    QToolBar* sessionToolBar = addToolBar(tr("Session"));
    sessionToolBar->setObjectName(QStringLiteral("sessionToolBar"));
    sessionToolBar->setMovable(false);
    sessionToolBar->addWidget(m_sessionBar);
    m_deviceDock = addDock(this, tr("Device"), QStringLiteral("deviceDock"), scrollingPanel(m_devicePanel),
                           Qt::LeftDockWidgetArea);
    m_deviceDock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
    resizeDocks({m_deviceDock}, {290}, Qt::Horizontal);
    m_xyPlot = new XYPlotWidget(this);
    m_xyPlot->setObjectName(QStringLiteral("xyPlot"));
    m_xyDock = addDock(this, tr("XY plot"), QStringLiteral("xyDock"), m_xyPlot, Qt::RightDockWidgetArea);
    m_xyDock->hide();  // on request (View menu): the mode views come first
    m_spectrum = new LiveSpectrum(*m_station, this);
    m_health = new LiveHealth(*m_station, this);
    m_rawConsole = new RawConsole(this);
    m_rawConsole->setObjectName(QStringLiteral("rawConsole"));
    m_consoleDock =
        addDock(this, tr("Raw data"), QStringLiteral("consoleDock"), m_rawConsole, Qt::BottomDockWidgetArea);
    m_consoleDock->hide();  // for troubleshooting a probe
    m_others = new OtherDevices(this);
    m_othersDock =
        addDock(this, tr("Other devices"), QStringLiteral("otherDevicesDock"), m_others, Qt::LeftDockWidgetArea);
    // Beside the device panel, tabs of their own: the window keeps its width.
    tabifyDockWidget(m_deviceDock, m_othersDock);
    tabifyDockWidget(m_deviceDock, m_spectrum->dock());
    tabifyDockWidget(m_deviceDock, m_health->dock());
    m_othersDock->hide();  // until a device is added
    m_status = new StatusLine(statusBar());
    m_central = new CentralStoreLink(statusBar(), this);
    connect(m_central, &CentralStoreLink::browseRequested, m_review, &ReviewWindows::showCentralBrowser);
}

// The live widgets watch the station; the window keeps what needs a
// dialog, the title and the plots' shared clock.
void MainWindow::watchStation()
{
    const auto tell = [this](const QString& text) { statusBar()->showMessage(text, 8000); };
    auto lanes = m_modeViews->lanes();
    lanes.push_back(m_signal->plot());
    m_traces = new LiveTraces(*m_station, m_plot, std::move(lanes), this);
    connect(m_signal, &SignalControl::tracesChanged, m_traces, &LiveTraces::setFilteredTraces);
    m_markers = new LiveMarkers(*m_station, *m_traces,
                                {.store = [this] { return m_store; },
                                 .author = [this] { return m_sessionBar->metadata().operatorName; },
                                 .tell = tell},
                                this);
    m_profiles = new LiveProfiles(*m_station,
                                  {.mode = [this] { return mode(); },
                                   .applied = [this](core::Mode applied) { m_modes->showMode(applied); },
                                   .tell = tell},
                                  this);
    m_modes = new ModeChoice(*m_station,
                             {.bar = m_sessionBar,
                              .views = m_modeViews,
                              .traces = m_traces,
                              .panel = m_devicePanel,
                              .xy = m_xyPlot,
                              .xyDock = m_xyDock},
                             tell, this);
    m_quit = new QuitQuestion(*m_station, this);
    m_status->watch(*m_station);
    m_rawConsole->watch(*m_station);
    m_devicePanel->watch(*m_station);
    m_sessionBar->watch(*m_station);
    m_modeViews->watch(*m_station, m_plot);
    m_others->watch(*m_station);
    m_handsFree = new HandsFreeControl(*m_station, m_watchBanner,
                                       {.metadata = [this] { return m_sessionBar->metadata(); },
                                        .refusal =
                                            [](const core::storage::SessionMetadata& metadata) {
                                                return recordingRefusal(recordingPolicy(),
                                                                        QString::fromStdString(metadata.subject),
                                                                        QString::fromStdString(metadata.operatorName));
                                            },
                                        .problem = [this](const Problem& problem) { reportProblem(this, problem); },
                                        .tell = tell},
                                       this);
    connect(m_sessionBar, &SessionBar::recordClicked, this, &MainWindow::toggleRecording);
    for (LiveModeView* view : m_modeViews->views()) {
        connect(view, &LiveModeView::profilesRequested, this, &MainWindow::showProfiles);
        connect(view, &LiveModeView::tareRequested, this, &MainWindow::tare);
    }
    connect(m_station, &LiveStation::problem, this, [this](const Problem& problem) { reportProblem(this, problem); });
    connect(m_station, &LiveStation::connectFailed, this,
            [this](const Problem& problem) { reportProblem(this, problem); });
    connect(m_station, &LiveStation::connected, this, &MainWindow::deviceConnected);
    connect(m_station, &LiveStation::disconnected, this, [this] {
        setWindowTitle(tr("Tactiscope"));
        m_othersDock->hide();
    });
    connect(m_station, &LiveStation::devicesChanged, this, [this] {
        if (m_others->empty() || m_othersDock->isVisible()) return;
        m_othersDock->show();
        m_othersDock->raise();
    });
    connect(m_station, &LiveStation::polled, this, [this](const devices::session::PipelineNews& news) {
        std::vector<std::string> problems;
        for (const auto& [device, problem] : news.problems) problems.push_back(problem);
        reportAnalysisProblems(this, problems);
        for (const auto& [device, summary] : news.partsEnded) tellPartEnded(this, device, summary);
    });
    connect(m_station, &LiveStation::recordingEnded, this, &MainWindow::recordingEnded);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_quit->mayClose()) return event->ignore();
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
                        .value_or(core::modeDefinitions().front().mode);
    metadata.operatorName = settings.value(QStringLiteral("session/operator")).toString().toStdString();
    metadata.subject = settings.value(QStringLiteral("session/subject")).toString().toStdString();
    m_sessionBar->setMetadata(metadata);
    m_station->setMode(metadata.mode);
    setStorePath(settings.value(QStringLiteral("recording/store"), defaultStorePath()).toString());
    m_modes->showView();
}

void MainWindow::saveSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    const auto metadata = m_sessionBar->metadata();
    settings.setValue(QStringLiteral("session/mode"), wordText(metadata.mode));
    settings.setValue(QStringLiteral("session/operator"), QString::fromStdString(metadata.operatorName));
    settings.setValue(QStringLiteral("session/subject"), QString::fromStdString(metadata.subject));
    settings.setValue(QStringLiteral("recording/store"), m_storePath);
}

void MainWindow::deviceConnected()
{
    setWindowTitle(tr("Tactiscope — %1").arg(QString::fromStdString(m_station->device()->source().name())));
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    // Ctrl+Q, as the guide says, whatever the platform's default for Quit.
    file->addAction(tr("&Quit"), QKeySequence(tr("Ctrl+Q")), qApp, &QApplication::closeAllWindows);

    QMenu* device = menuBar()->addMenu(tr("&Device"));
    device->addAction(tr("&Choose a device…"), QKeySequence(tr("Ctrl+K")), this, [this] {
        m_deviceDock->show();
        m_deviceDock->raise();
        m_devicePanel->setFocus();
    });
    QMenu* simulator = device->addMenu(tr("&Simulator"));
    for (const std::string& id : devices::simulator::scenarioIds())
        simulator->addAction(QString::fromStdString(id), this, [this, id] { m_station->connectSimulator(id); });
    device->addSeparator();
    device->addAction(tr("&Disconnect"), m_station, &LiveStation::disconnectDevices);

    QMenu* session = menuBar()->addMenu(tr("&Session"));
    session->addAction(tr("Start / stop &recording"), QKeySequence(tr("Ctrl+R")), this, &MainWindow::toggleRecording);
    session->addAction(tr("&Mark event"), QKeySequence(tr("Ctrl+M")), this, [this] { m_markers->mark(); });
    session->addAction(tr("Mark event with a &note…"), QKeySequence(tr("Ctrl+Shift+M")), m_markers,
                       &LiveMarkers::markWithNote);
    session->addAction(tr("&Tare"), QKeySequence(tr("Ctrl+T")), this, &MainWindow::tare);
    session->addSeparator();
    m_handsFree->addActions(session);
    m_signal->addActions(session);
    session->addSeparator();
    session->addAction(tr("Sensor &profiles…"), QKeySequence(tr("Ctrl+Shift+P")), this, &MainWindow::showProfiles);
    session->addAction(tr("Session &store…"), this, &MainWindow::chooseStore);
    session->addAction(tr("&Central store…"), this, [this] { m_central->showDialog(); });
    session->addAction(tr("&Browse and review sessions…"), QKeySequence::Open, this, &MainWindow::showSessionBrowser);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock :
         {m_deviceDock, m_othersDock, m_xyDock, m_spectrum->dock(), m_health->dock(), m_consoleDock})
        view->addAction(dock->toggleViewAction());
    view->addAction(m_signal->filteredTracesAction());
    view->addSeparator();
    QToolBar* display = addToolBar(tr("Display"));
    display->setObjectName(QStringLiteral("displayToolBar"));
    display->setMovable(false);
    display->setToolButtonStyle(Qt::ToolButtonTextOnly);
    addPlotControls(view, display,
                    {.plots = [this] { return m_traces->plots(); },
                     .windowChanged = [this](double seconds) { m_xyPlot->setWindowLength(seconds); }});

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    // Each mode's calibration wizard and tool (ui/modes/ModeUi.h).
    addCalibrationActions(
        tools, *m_station,
        [this] {
            return LiveCalibration{.storePath = m_storePath,
                                   .store = m_store,
                                   .operatorName = QString::fromStdString(m_sessionBar->metadata().operatorName),
                                   .profileDirectory = ProfileLibrary::defaultDirectory(),
                                   .tell = [this](const QString& text) { statusBar()->showMessage(text, 8000); },
                                   .applied = [this](core::Mode calibrated) { m_modes->showMode(calibrated); }};
        },
        this);
    tools->addSeparator();
    tools->addAction(tr("&Settings…"), this, [this] { showSettingsDialog(this); });
    for (const auto& definition : core::modeDefinitions())
        if (const auto& ui = modeUi(definition.mode); ui.toolAction && ui.openTool)
            tools->addAction(ui.toolAction(), this, [this, open = ui.openTool] { open(this); });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User guide"), QKeySequence::HelpContents, this,
                    [this] { showUserGuide(this, QCoreApplication::applicationDirPath()); });
    help->addAction(tr("&Keyboard shortcuts"), this, [this] {
        showKeyboardShortcuts({{tr("Main window"), menuShortcuts(*menuBar())},
                               {tr("Session browser"), SessionBrowser::helpRows()},
                               {tr("Review window"), ReviewActions::helpRows()}},
                              this);
    });
    help->addSeparator();
    help->addAction(tr("&About Tactiscope"), this,
                    [this] { QMessageBox::about(this, tr("About Tactiscope"), aboutText()); });
}

LiveModeView* MainWindow::modeView(core::Mode mode) const
{
    return m_modeViews->view(mode);
}

void MainWindow::setStorePath(const QString& path)
{
    m_storePath = path;
    m_store = std::make_shared<core::storage::StoreWorker>(path.toStdString());
    m_review->setStore(m_store);
    m_sessionBar->setStorePath(path);
    m_central->setStorePath(path);
    m_station->setStorePath(path);
}

void MainWindow::chooseStore()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Session store"), m_storePath,
                                                      tr("Tactiscope session stores (*.tactiscope);;All files (*)"),
                                                      nullptr, QFileDialog::DontConfirmOverwrite);
    if (!path.isEmpty()) useStore(path);
}

// A file that is there must be a store already: a CSV or a damaged file is
// refused when chosen, with the reason, and the store stays what it was.
// (A new path is a store to be made: the first recording creates it.)
bool MainWindow::useStore(const QString& path)
{
    if (isRecording()) {
        reportProblem(this, {tr("Session store not changed"), tr("A recording is going to %1.").arg(m_storePath),
                             tr("A recording keeps its session store to its end."),
                             tr("Stop the recording, then choose the store."), QStringLiteral("storeRefusedBox")});
        return false;
    }
    if (QFileInfo::exists(path)) {
        try {
            core::storage::SessionStore probe(path.toStdString(), core::storage::Database::Access::ReadOnly);
            probe.refuseIfDamaged();
        } catch (const core::storage::StorageError& e) {
            reportProblem(this, {tr("Not a session store"),
                                 tr("%1 cannot be the session store.").arg(QDir::toNativeSeparators(path)),
                                 QString::fromStdString(e.what()),
                                 tr("Sessions still go to %1.").arg(QDir::toNativeSeparators(m_storePath)),
                                 QStringLiteral("storeRefusedBox")});
            return false;
        }
    }
    setStorePath(path);  // the devices record there and read its calibrations (problems: next poll)
    m_modes->showMode(mode());
    checkStore();
    return true;
}

bool MainWindow::setMode(core::Mode mode)
{
    return m_modes->setMode(mode);
}

core::Mode MainWindow::mode() const
{
    return m_sessionBar->metadata().mode;
}

bool MainWindow::isRecording() const
{
    return m_station->isRecording();
}

void MainWindow::checkStore()
{
    m_review->checkStore();
}

SessionBrowser* MainWindow::showSessionBrowser()
{
    return m_review->showBrowser();
}

void MainWindow::reviewSessions(const std::vector<std::int64_t>& sessions)
{
    m_review->review(sessions);
}

void MainWindow::toggleRecording()
{
    if (m_station->armed())  // the button disarms: an open triggered session ends as complete
        m_station->disarmTrigger();
    else if (isRecording())
        stopRecording();
    else
        startRecording();
}

bool MainWindow::startRecording()
{
    if (isRecording()) return true;
    const auto metadata = m_sessionBar->metadata();
    if (const QString refusal = recordingRefusal(recordingPolicy(), QString::fromStdString(metadata.subject),
                                                 QString::fromStdString(metadata.operatorName));
        !refusal.isEmpty()) {
        reportProblem(
            this,
            {tr("Cannot record"), tr("Recording did not start."), refusal, {}, QStringLiteral("recordRefusedBox")});
        return false;
    }
    if (!m_station->isConnected()) {
        statusBar()->showMessage(tr("Connect a device to record."), 5000);
        return false;
    }
    if (const auto error = m_station->startRecording(metadata)) {
        reportProblem(this, {tr("Cannot record"), tr("Recording could not start."), *error,
                             tr("Choose another session store (Session ▸ Session store…) or free space on its "
                                "disk, then record again.")});
        return false;
    }
    return true;
}

void MainWindow::stopRecording()
{
    m_station->stopRecording();
}

void MainWindow::recordingEnded(const devices::session::RecordingEnd& end)
{
    m_review->sessionRecorded();
    m_central->sessionRecorded();
    VerdictDialog* asked = tellRecordingEnd(
        end, {.window = this,
              .store = m_store,
              .operatorName = m_sessionBar->metadata().operatorName,
              .tell = [this](const QString& text) { statusBar()->showMessage(text, 8000); },
              .verdictSaved = [this] { m_central->syncNow(); }});  // the operator's verdict follows the session
    m_quit->recordingEnded(asked);
}

SensorProfileDialog* MainWindow::showProfiles()
{
    return m_profiles->show();
}

void MainWindow::tare()
{
    const auto refusal = m_station->tare();
    statusBar()->showMessage(refusal ? tr("Not tared: %1").arg(*refusal)
                                     : tr("Tared: the last half second is the new zero"),
                             refusal ? 8000 : 4000);
}

}  // namespace tactiscope::ui
