// MainWindow: wiring of the live session, the plots, menus and status bar.
#include "ui/MainWindow.h"

#include "ui/central/CentralStoreLink.h"

#include "core/ModeCapability.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/SessionStore.h"
#include "core/storage/StoreWorker.h"
#include "devices/session/LiveSession.h"
#include "devices/session/SessionOfDevices.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "ui/AboutText.h"
#include "ui/ActiveProfiles.h"
#include "ui/ChannelRolesBox.h"
#include "ui/DesignTool.h"
#include "ui/DeviceConnector.h"
#include "ui/DevicePanel.h"
#include "ui/ElidedTextTips.h"
#include "ui/HandsFreeControl.h"
#include "ui/HelpWindows.h"
#include "ui/InterruptedSessionsReport.h"
#include "ui/LinkStatus.h"
#include "ui/LivePlotWidget.h"
#include "ui/MarkerNote.h"
#include "ui/ModeViews.h"
#include "ui/ModeXY.h"
#include "ui/NumberText.h"
#include "ui/OtherDevices.h"
#include "ui/PlotControls.h"
#include "ui/ProblemReport.h"
#include "ui/RawConsole.h"
#include "ui/RecordingPolicy.h"
#include "ui/SensorProfileDialog.h"
#include "ui/SessionBar.h"
#include "ui/StatusLine.h"
#include "ui/StoreJobs.h"
#include "ui/VerdictDialog.h"
#include "ui/VocabularyText.h"
#include "ui/WatchBanner.h"
#include "ui/XYPlotWidget.h"
#include "ui/calibration/CalibrationHistory.h"
#include "ui/calibration/CalibrationWizards.h"
#include "ui/calibration/ShuntCheckDialog.h"
#include "ui/modes/LiveModeView.h"
#include "ui/modes/ModeUi.h"
#include "ui/review/ReviewActions.h"
#include "ui/review/ReviewWindows.h"
#include "ui/review/SessionBrowser.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QIcon>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {
namespace {

constexpr int kStatusInterval_ms = 250;

QString defaultStorePath()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("sessions.tactiscope"));
}

Problem badProfile(const QString& mode, const QString& error)
{
    return {MainWindow::tr("Bad profile"),
            MainWindow::tr("The %1 profile could not be used; the paper's sensor is used instead.").arg(mode), error,
            MainWindow::tr("Fix or choose another profile in Session ▸ Sensor profiles.")};
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
      m_plot(new LivePlotWidget(this)),
      m_modeViews(new ModeViews(this)),
      m_devicePanel(new DevicePanel(this)),
      m_review(new ReviewWindows(this))
{
    ElidedTextTips::install();  // every cut cell and combo of every window says its whole text
    setWindowTitle(tr("Tactiscope"));
    setWindowIcon(QIcon(QStringLiteral(":/tactiscope/icons/tactiscope.svg")));
    // The traces on top, the mode's view (its lanes, readings and controls) below.
    auto* centre = new QSplitter(Qt::Vertical, this);
    centre->setObjectName(QStringLiteral("centreSplitter"));
    centre->addWidget(m_plot);
    // One mode view at a time, in one splitter pane whose height the user sets.
    centre->addWidget(m_modeViews);
    // Half and half: on a 768-pixel screen the mode's view (its readings,
    // the tissue scale, the site map) needs the room as much as the traces.
    centre->setStretchFactor(0, 1);
    centre->setStretchFactor(1, 1);
    centre->setSizes({400, 400});
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
    connect(m_sessionBar, &SessionBar::recordClicked, this, &MainWindow::toggleRecording);
    connect(m_sessionBar, &SessionBar::modeChanged, this, &MainWindow::modeChosen);
    m_deviceDock = addDock(this, tr("Device"), QStringLiteral("deviceDock"), m_devicePanel, Qt::LeftDockWidgetArea);
    m_deviceDock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
    resizeDocks({m_deviceDock}, {290}, Qt::Horizontal);
    m_xyPlot = new XYPlotWidget(this);
    m_xyPlot->setObjectName(QStringLiteral("xyPlot"));
    m_xyDock = addDock(this, tr("XY plot"), QStringLiteral("xyDock"), m_xyPlot, Qt::RightDockWidgetArea);
    m_xyDock->hide();  // on request (View menu): the mode views come first
    m_rawConsole = new RawConsole(this);
    m_rawConsole->setObjectName(QStringLiteral("rawConsole"));
    m_consoleDock =
        addDock(this, tr("Raw data"), QStringLiteral("consoleDock"), m_rawConsole, Qt::BottomDockWidgetArea);
    m_consoleDock->hide();  // for troubleshooting a probe
    for (LiveModeView* view : m_modeViews->views()) {
        connect(view, &LiveModeView::profilesRequested, this, &MainWindow::showProfiles);
        connect(view, &LiveModeView::tareRequested, this, &MainWindow::tare);
    }
    m_status = new StatusLine(statusBar());
    m_central = new CentralStoreLink(statusBar(), this);
    connect(m_central, &CentralStoreLink::browseRequested, m_review, &ReviewWindows::showCentralBrowser);
    m_connector = new DeviceConnector(
        {[this] { disconnectSource(); },
         [this](const QString& label) {
             m_status->setDevice(label);
             m_status->setLink(tr("Connecting…"));
             m_devicePanel->setConnecting(label);
         },
         [this](std::unique_ptr<devices::BlockSource> source, std::shared_ptr<devices::simulator::LoadRig> rig) {
             connectSource(std::move(source));
             m_loadRig = std::move(rig);  // after connectSource, which forgets the old device's rig
         },
         [this](const Problem& problem) {
             m_devicePanel->setConnected(false);
             m_devicePanel->clearCounters(tr("Connection failed"));
             m_status->setLink(tr("Connection failed"));
             reportProblem(this, problem);
         }},
        this);
    connect(m_devicePanel, &DevicePanel::connectRequested, m_connector, &DeviceConnector::request);
    m_others = new OtherDevices(this);
    m_othersDock =
        addDock(this, tr("Other devices"), QStringLiteral("otherDevicesDock"), m_others, Qt::RightDockWidgetArea);
    m_othersDock->hide();  // until a device is added
    m_adder = new DeviceConnector(
        {[] {},  // the window's device stays
         [this](const QString& label) { statusBar()->showMessage(tr("Connecting to %1…").arg(label)); },
         [this](std::unique_ptr<devices::BlockSource> source, std::shared_ptr<devices::simulator::LoadRig>) {
             addOtherDevice(std::move(source));
         },
         [this](const Problem& problem) { reportProblem(this, problem); }},
        this);
    connect(m_devicePanel, &DevicePanel::addRequested, this, [this](const SourceRequest& request) {
        if (isRecording() || m_handsFree->armed()) {
            statusBar()->showMessage(tr("Stop recording first: a session keeps the devices it started with."), 6000);
            return;
        }
        m_adder->request(request);
    });
    connect(m_others, &OtherDevices::removeRequested, this, [this](std::size_t index) {
        if (isRecording()) {
            statusBar()->showMessage(tr("Stop recording first: a session keeps the devices it started with."), 6000);
            return;
        }
        m_others->remove(index);
    });
    connect(m_devicePanel, &DevicePanel::disconnectRequested, this, &MainWindow::disconnectSource);
    connect(m_devicePanel->rolesBox(), &ChannelRolesBox::rolesChosen, this, &MainWindow::setRoles);
    m_handsFree = new HandsFreeControl(
        m_watchBanner,
        {[this] { return m_session.get(); }, [this] { return m_sessionBar->metadata(); },
         [this](const core::storage::SessionMetadata& metadata) {
             if (!m_others->empty())
                 return tr("A trigger records the window's device alone: remove the other devices first (View ▸ "
                           "Other devices).");
             return recordingRefusal(recordingPolicy(), QString::fromStdString(metadata.subject),
                                     QString::fromStdString(metadata.operatorName));
         },
         [this](const devices::session::RecordingSummary& summary) { recordingEnded(summary, true); },
         [this](const Problem& problem) { reportProblem(this, problem); },
         [this](const QString& text) { statusBar()->showMessage(text, 8000); },
         [this] {
             m_sessionBar->setArmed(m_handsFree->armed());
             m_sessionBar->setRecording(isRecording());
             lockProfiles();
         }},
        this);
    createMenus();
    linkPlots();
    restoreSettings();
    // The keyboard starts on the traces, where a stray key does nothing: not
    // in the detector's threshold (the first spin box in the tab order), nor
    // in a text field that would take Ctrl+K and Ctrl+H for itself.
    m_plot->setFocusPolicy(Qt::StrongFocus);
    m_plot->setFocus();
    m_statusTimer.setInterval(kStatusInterval_ms);
    connect(&m_statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
}

MainWindow::~MainWindow()
{
    disconnectSource();  // ends a recording, with everything kept
}

// Quitting while recording asks first: stopping ends the session (with its
// verdict step in a mode that has one, the operator's to answer), so the
// window stays for it.
void MainWindow::closeEvent(QCloseEvent* event)
{
    if (isRecording()) {
        event->ignore();
        askToStopBeforeQuitting();
        return;
    }
    saveSettings();
    event->accept();
}

void MainWindow::askToStopBeforeQuitting()
{
    if (findChild<QMessageBox*>(QStringLiteral("quitWhileRecordingBox"))) return;  // asked already
    auto* box = new QMessageBox(QMessageBox::Question, tr("Recording"),
                                tr("Session %1 is recording. Stop it before quitting?").arg(m_session->sessionId()),
                                QMessageBox::NoButton, this);
    box->setObjectName(QStringLiteral("quitWhileRecordingBox"));
    // Only the modes with a verdict ask for one at the stop.
    box->setInformativeText(core::definitionOf(mode()).detectsDefects
                                ? tr("Stopping ends the session and asks for its verdict; quit once that is done.")
                                : tr("Stopping ends the session and keeps every sample; then quit."));
    QPushButton* stop = box->addButton(tr("Stop recording"), QMessageBox::AcceptRole);
    stop->setObjectName(QStringLiteral("stopForQuitButton"));
    QPushButton* keep = box->addButton(tr("Keep recording"), QMessageBox::RejectRole);
    keep->setObjectName(QStringLiteral("keepRecordingButton"));
    box->setDefaultButton(keep);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(stop, &QPushButton::clicked, this, &MainWindow::stopRecording);
    box->open();
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
    setStorePath(settings.value(QStringLiteral("recording/store"), defaultStorePath()).toString());
    showModeView();
}

void MainWindow::showModeView()
{
    const auto shown = m_modeViews->show(m_session.get(), m_sessionBar->metadata().mode);
    m_xyDock->setWindowTitle(showModeXY(*m_xyPlot, m_session.get(), shown));
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
            const QString device = QString::fromStdString(m_session->source().name());
            reportProblem(this, {tr("Mode not available"), tr("%1 cannot run on %2.").arg(modeTitle(chosen), device),
                                 QString::fromStdString(*refusal),
                                 tr("The session stays in %1. Give the device's channels roles in the device "
                                    "panel (Channel roles: %2), or connect the probe made for %3.")
                                     .arg(modeTitle(m_session->mode()),
                                          QString::fromStdString(core::roleExample(chosen, m_session->channels()))
                                              .replace(QLatin1Char(','), QStringLiteral(", ")),
                                          modeTitle(chosen)),
                                 QStringLiteral("modeRefusedBox")});
        }
    }
    showModeView();
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
    for (const std::string& id : devices::simulator::scenarioIds()) {
        simulator->addAction(QString::fromStdString(id), this, [this, id] { m_connector->connectSimulator(id); });
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
    m_handsFree->addActions(session);
    session->addSeparator();
    session->addAction(tr("Sensor &profiles…"), QKeySequence(tr("Ctrl+Shift+P")), this, &MainWindow::showProfiles);
    session->addAction(tr("Session &store…"), this, &MainWindow::chooseStore);
    session->addAction(tr("&Central store…"), this, [this] { m_central->showDialog(); });
    session->addAction(tr("&Browse and review sessions…"), QKeySequence::Open, this, &MainWindow::showSessionBrowser);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_deviceDock->toggleViewAction());
    view->addAction(m_othersDock->toggleViewAction());
    view->addAction(m_xyDock->toggleViewAction());
    view->addAction(m_consoleDock->toggleViewAction());
    view->addSeparator();
    QToolBar* display = addToolBar(tr("Display"));
    display->setObjectName(QStringLiteral("displayToolBar"));
    display->setMovable(false);
    display->setToolButtonStyle(Qt::ToolButtonTextOnly);
    addPlotControls(view, display,
                    {[this] { return allPlots(); }, [this](double seconds) { m_xyPlot->setWindowLength(seconds); }});

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    // Each mode that reads a stored calibration, by its wizard (ui/modes/ModeUi.h).
    for (const auto& definition : core::modeDefinitions())
        if (const auto action = modeUi(definition.mode).calibrateAction)
            tools->addAction(action(), this, [this, mode = definition.mode] { calibrate(mode); });
    QAction* shunt = tools->addAction(tr("Sh&unt check…"), this, [this] {
        if (!m_session) return statusBar()->showMessage(tr("Connect a probe to check its bridges."), 5000);
        auto* dialog = new ShuntCheckDialog({[this] { return m_session.get(); }, m_storePath,
                                             QString::fromStdString(m_sessionBar->metadata().operatorName)},
                                            this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    shunt->setObjectName(QStringLiteral("shuntCheckAction"));
    tools->addAction(tr("Calibration &history…"), this, [this] {
        auto* history = new CalibrationHistory(m_storePath, this);
        history->setAttribute(Qt::WA_DeleteOnClose);
        history->show();
    });
    tools->addSeparator();
    tools->addAction(tr("&Settings…"), this, [this] { showSettingsDialog(this); });
    tools->addAction(tr("Compliance probe &design…"), this, [this] {
        auto* tool = new DesignTool(ProfileLibrary::defaultDirectory(), this);
        tool->setAttribute(Qt::WA_DeleteOnClose);
        tool->show();
    });

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
    help->addAction(tr("&About Tactiscope"), this, &MainWindow::showAbout);
}

std::vector<LivePlotWidget*> MainWindow::allPlots() const
{
    std::vector<LivePlotWidget*> plots{m_plot};
    for (LivePlotWidget* lanes : m_modeViews->lanes()) plots.push_back(lanes);
    return plots;
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
}

void MainWindow::chooseStore()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Session store"), m_storePath,
                                                      tr("Tactiscope session stores (*.tactiscope);;All files (*)"),
                                                      nullptr, QFileDialog::DontConfirmOverwrite);
    if (path.isEmpty()) return;
    useStore(path);
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
    setStorePath(path);
    if (m_session) {
        // The live session records there from now on and reads its calibrations.
        m_session->setStorePath(path.toStdString());
        showMode(m_sessionBar->metadata().mode);
        reportSessionProblems();
    }
    checkStore();
    return true;
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
    if (m_handsFree->armed())  // the button disarms: an open triggered session ends as complete
        m_handsFree->disarm();
    else if (isRecording())
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
    const auto metadata = m_sessionBar->metadata();
    if (const QString refusal = recordingRefusal(recordingPolicy(), QString::fromStdString(metadata.subject),
                                                 QString::fromStdString(metadata.operatorName));
        !refusal.isEmpty()) {
        reportProblem(
            this,
            {tr("Cannot record"), tr("Recording did not start."), refusal, {}, QStringLiteral("recordRefusedBox")});
        return false;
    }
    if (!m_others->empty()) return startRecordingDevices(metadata);
    if (const auto error = m_session->startRecording(metadata)) {
        reportProblem(this, {tr("Cannot record"), tr("Recording could not start."), QString::fromStdString(*error),
                             tr("Choose another session store (Session ▸ Session store…) or free space on its "
                                "disk, then record again.")});
        return false;
    }
    m_sessionBar->setRecording(true);
    lockProfiles();
    updateRecording();
    return true;
}

bool MainWindow::startRecordingDevices(const core::storage::SessionMetadata& metadata)
{
    const auto refused = [this](const QString& why) {
        reportProblem(this, {tr("Cannot record"), tr("Recording of the devices did not start."), why,
                             tr("Check the session store and each device, then record again.")});
        return false;
    };
    try {
        m_devicesSession = std::make_unique<devices::session::SessionOfDevices>(m_storePath.toStdString(), metadata);
    } catch (const core::storage::StorageError& e) {
        return refused(QString::fromStdString(e.what()));
    }
    if (const auto error = m_session->startRecordingPart(metadata, m_devicesSession->partFor(deviceName()))) {
        m_devicesSession.reset();  // ends the session, with no part, as interrupted
        return refused(QString::fromStdString(deviceName() + ": " + *error));
    }
    if (const auto error = m_others->startParts(metadata, *m_devicesSession)) {
        m_session->stopRecording();
        m_devicesSession.reset();
        return refused(QString::fromStdString(*error));
    }
    m_sessionBar->setRecording(true);
    lockProfiles();
    updateRecording();
    return true;
}

devices::session::RecordingSummary MainWindow::endRecordingDevices(devices::session::RecordingSummary summary)
{
    const std::vector<std::string> problems = m_others->stopParts();
    try {
        m_devicesSession->finish();
    } catch (const core::storage::StorageError& e) {
        if (summary.stats.error.empty()) summary.stats.error = e.what();
    }
    summary.session = m_devicesSession->sessionId();
    // Each part keeps its device's own analysis; the session of several
    // has no one automatic verdict to confirm.
    summary.verdict.reset();
    m_devicesSession.reset();
    for (const std::string& problem : problems)
        reportProblem(this,
                      {tr("Device stopped"), tr("One device's part of session %1 ended early.").arg(summary.session),
                       QString::fromStdString(problem),
                       tr("Its samples up to then are kept in its part; the others recorded on.")});
    return summary;
}

std::string MainWindow::deviceName() const
{
    return m_session ? devices::session::partName(m_session->source().identity(), {}) : std::string{};
}

void MainWindow::addOtherDevice(std::unique_ptr<devices::BlockSource> source)
{
    if (!m_session || isRecording()) return;  // the window's device went, or a recording began meanwhile
    devices::session::LiveSessionOptions options;
    options.storePath = m_storePath.toStdString();
    options.displaySeconds = LivePlotWidget::kMaxWindow_s + 2.0;
    const QString name = QString::fromStdString(source->name());
    m_others->add(std::move(source), std::move(options), {deviceName()});
    m_othersDock->show();
    statusBar()->showMessage(
        tr("%1 added: Record records it with %2 into one session.").arg(name, QString::fromStdString(deviceName())),
        8000);
}

void MainWindow::stopRecording()
{
    if (!isRecording()) return;
    if (const auto summary = m_session->stopRecording()) recordingEnded(*summary);
}

void MainWindow::recordingEnded(const devices::session::RecordingSummary& ended, bool triggered)
{
    const devices::session::RecordingSummary summary = m_devicesSession ? endRecordingDevices(ended) : ended;
    m_sessionBar->setRecording(false);
    if (m_session) {
        // The lists now hold exactly what the session stored: shown at once.
        m_modeViews->update(*m_session);
        showDefectsOnTraces();
    }
    m_review->sessionRecorded();
    m_central->sessionRecorded();
    lockProfiles();
    m_sessionBar->setRecordEnabled(m_session != nullptr);
    m_status->showSaved(summary.session, summary.stats);
    if (!summary.stats.error.empty())
        reportProblem(this, {tr("Recording stopped"), tr("Recording stopped early."),
                             QString::fromStdString(summary.stats.error),
                             tr("The samples up to the stop are kept in session %1. Free space or choose another "
                                "store, then record again.")
                                 .arg(summary.session)});
    else if (summary.lostAt_s)
        reportProblem(this, {tr("Probe lost"),
                             tr("The probe was lost at %1 s and did not come back before the stop.")
                                 .arg(fixedText(*summary.lostAt_s, 1)),
                             QString::fromStdString(summary.stoppedBecause),
                             tr("Session %1 keeps every sample up to the loss; the time after it is a gap with an "
                                "alarm. Check the cable and the probe, then record again.")
                                 .arg(summary.session)});
    else if (!summary.stoppedBecause.empty())
        reportProblem(this, {tr("Recording stopped"), tr("The link to the probe failed, so the recording stopped."),
                             QString::fromStdString(summary.stoppedBecause),
                             tr("Session %1 keeps every sample up to then, with an alarm; nothing after it was "
                                "recorded. Connect the probe again and record to start a new session.")
                                 .arg(summary.session)});
    else if (triggered)
        statusBar()->showMessage(tr("Session %1 (%2) recorded by the trigger: %3")
                                     .arg(summary.session)
                                     .arg(QString::fromStdString(m_session->recordingMetadata().subject),
                                          QString::fromStdString(summary.analysis)),
                                 8000);
    else if (summary.verdict)
        askVerdict(this, m_store,
                   {summary.session, static_cast<int>(summary.defects), static_cast<int>(summary.sites),
                    *summary.verdict, m_sessionBar->metadata().operatorName},
                   [this](const QString& message) {
                       statusBar()->showMessage(message, 5000);
                       m_central->syncNow();  // the operator's verdict follows the session
                   });
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
    m_devicePanel->rolesBox()->setLocked(isRecording());
}

void MainWindow::applyProfile(const QString& modeName)
{
    const auto mode = core::modeFromString(modeName.toStdString());
    if (!m_session || !mode) return;  // the next connection reads it
    ActiveProfile active = activeProfile(modeName);
    if (!active.error.isEmpty()) reportProblem(this, badProfile(modeName, active.error));
    if (const auto refusal = m_session->setProfile(*mode, std::move(active.profile))) {
        reportProblem(this, {tr("Bad profile"), tr("The %1 probe was not changed.").arg(modeName),
                             QString::fromStdString(*refusal), tr("Fix the profile in Session ▸ Sensor profiles.")});
        return;
    }
    showMode(*mode);
    if (m_session->unit(*mode))
        statusBar()->showMessage(tr("New %1 profile: its factors apply to the zero in use").arg(modeTitle(*mode)),
                                 5000);
}

// Roles chosen in the device panel: the processors are rebuilt on them and
// the bar's mode runs when it now can; the choice is kept for the device.
void MainWindow::setRoles(const core::RoleAssignment& roles)
{
    if (!m_session) return;
    if (const auto refusal = m_session->setRoles(roles)) {
        reportProblem(
            this,
            {tr("Roles not changed"), tr("The channels keep their roles."), QString::fromStdString(*refusal), {}});
        m_devicePanel->rolesBox()->setChannels(m_session->source().channels(), m_session->roles(),
                                               m_devicePanel->rolesBox()->isOpen());
        return;
    }
    rememberRoles(m_session->source().identity(), roles);
    reportSessionProblems();
    const core::Mode wanted = m_sessionBar->metadata().mode;
    if (!m_session->refusalOf(wanted)) m_session->setMode(wanted);
    {
        const QSignalBlocker quiet(m_sessionBar);
        m_sessionBar->setMode(m_session->mode());
    }
    m_modeViews->bindAll(m_session.get());
    m_plot->setSource(m_session->buffer(), m_session->channels(), m_session->source().nominalSampleRate_hz());
    showModeView();
    statusBar()->showMessage(tr("Channel roles set: %1 runs on %2")
                                 .arg(modeTitle(m_session->mode()), QString::fromStdString(m_session->source().name())),
                             5000);
}

void MainWindow::showMode(core::Mode mode)
{
    m_modeViews->bind(m_session.get(), mode);
    showModeView();
}

// Calibrating needs the live signal and must not change the calibration of
// a session being recorded.
void MainWindow::calibrate(core::Mode mode)
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
    CalibrationContext context{m_session->buffer(), m_session->channels(), m_session->source().nominalSampleRate_hz(),
                               m_loadRig, m_store, QString::fromStdString(m_sessionBar->metadata().operatorName),
                               ProfileLibrary::defaultDirectory(),
                               // The device's clock while it is this session's (a wizard may outlive it).
                               [this, session = m_session.get()] {
                                   return m_session.get() == session ? session->source().hostClock() : std::nullopt;
                               }};
    openCalibrationWizard(mode, std::move(context), this, [this, mode](const QString& sensor) {
        if (m_session) {
            if (const auto problem = m_session->reloadCalibrations(mode))
                reportProblem(
                    this, {tr("Calibration not applied"),
                           tr("The %1 view does not read through the new calibration.").arg(modeTitle(mode).toLower()),
                           QString::fromStdString(*problem),
                           {}});
            reportSessionProblems();
        }
        showMode(mode);
        statusBar()->showMessage(
            tr("Calibration of %1 stored; the %2 view reads through it.").arg(sensor, modeTitle(mode).toLower()), 8000);
    });
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

// A note entered after the recording ended still reaches its session, as
// an annotation at the marker's time.
void MainWindow::markEventWithNote()
{
    if (!isRecording()) {
        markEvent();  // says why not
        return;
    }
    const double time_s = m_session->sessionTime_s();
    const std::int64_t session = m_session->sessionId();
    askMarkerNote(this, time_s, [this, time_s, session, store = m_store](const QString& note) {
        if (isRecording() && m_session->sessionId() == session) {
            addMarker(time_s, note);
            return;
        }
        core::storage::Annotation annotation{0,  time_s, m_sessionBar->metadata().operatorName, note.toStdString(),
                                             "", ""};
        runOnStore(
            *store, this,
            [session, annotation](core::storage::SessionSource& s) { s.addAnnotation(session, annotation); },
            [this, session] { statusBar()->showMessage(tr("Note stored in session %1").arg(session), 5000); },
            [this, note](const QString& error) {
                reportProblem(this, {tr("Note not stored"), tr("The marker's note could not be stored."), error,
                                     tr("Your note: %1").arg(note)});
            });
    });
}

void MainWindow::addMarker(double time_s, const QString& note)
{
    m_session->addMarker(time_s, note.toStdString());
    if (const auto origin = m_session->recordingOrigin_s())
        for (LivePlotWidget* plot : allPlots()) plot->addMarker(*origin + time_s, note);
    statusBar()->showMessage(tr("Marker at %1 s").arg(fixedText(time_s, 2)), 4000);
}

void MainWindow::updateRecording()
{
    if (!isRecording()) return;
    m_sessionBar->setElapsed(m_session->sessionTime_s());
    m_status->showRecording(m_session->sessionId(), m_session->recorderStats());
}

void MainWindow::connectDevice(const QString& label, devices::ReconnectingSource::Opener opener)
{
    m_connector->open(label, std::move(opener));
}

bool MainWindow::isConnecting() const
{
    return m_connector->connecting().has_value();
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
        if (!active.error.isEmpty()) reportProblem(this, badProfile(mode, active.error));
        options.profiles.emplace(*core::modeFromString(mode.toStdString()), std::move(active.profile));
    }
    // The roles remembered for this device, for the channels it still has.
    for (const auto& [channel, role] : rememberedRoles(source->identity()))
        if (std::ranges::find(source->channels(), channel, &core::ChannelDescriptor::name) != source->channels().end())
            options.roles.emplace(channel, role);
    m_session = std::make_unique<devices::session::LiveSession>(std::move(source), std::move(options));
    // Open for a device that feeds no mode by itself (it starts in one that
    // needs no roles), or was given roles.
    m_devicePanel->rolesBox()->setChannels(m_session->source().channels(), m_session->roles(),
                                           core::definitionOf(m_session->declaredMode()).roles.empty() ||
                                               !m_session->roles().empty());
    reportSessionProblems();
    // The source's own mode wins; a source that declares none keeps the
    // bar's mode if its channels can feed it.
    const core::Mode chosen = m_sessionBar->metadata().mode;
    if (!m_session->source().declaredMode() && !m_session->refusalOf(chosen)) m_session->setMode(chosen);
    if (m_session->mode() != chosen) {
        const QSignalBlocker quiet(m_sessionBar);
        m_sessionBar->setMode(m_session->mode());
        // Told once the window is up: a message shown while it is hidden
        // leaves the status bar's device label drawn underneath it.
        const QString told = tr("Mode: %1, the mode of %2")
                                 .arg(modeTitle(m_session->mode()), QString::fromStdString(m_session->source().name()));
        QTimer::singleShot(0, this, [this, told] { statusBar()->showMessage(told, 6000); });
    }
    m_modeViews->bindAll(m_session.get());
    showModeView();
    const auto& device = m_session->source();
    m_plot->setSource(m_session->buffer(), m_session->channels(), device.nominalSampleRate_hz());
    m_session->start();

    const QString name = QString::fromStdString(device.name());
    setWindowTitle(tr("Tactiscope — %1").arg(name));
    m_status->setDevice(name);
    m_devicePanel->setConnected(true, name);
    m_rawConsole->setSource(&device);
    updateStatus();
    m_statusTimer.start();
    m_sessionBar->setRecordEnabled(true);
}

void MainWindow::disconnectSource()
{
    m_defectsOnTraces = 0;
    m_connector->cancel();  // a connect still in its handshake is dropped when it answers
    m_handsFree->disarm();  // an open triggered session ends as complete
    stopRecording();        // the user ended the session by disconnecting
    m_statusTimer.stop();
    m_rawConsole->setSource(nullptr);  // before the source goes
    m_plot->clearSource();
    m_modeViews->bindAll(nullptr);
    m_others->clear();  // they were recorded with this device
    m_othersDock->hide();
    m_session.reset();
    m_handsFree->disconnected();
    m_sessionBar->setArmed(false);
    m_loadRig.reset();
    showModeView();
    setWindowTitle(tr("Tactiscope"));
    m_status->setDevice({});
    m_status->setLink({});
    m_devicePanel->setConnected(false);
    m_devicePanel->rolesBox()->setChannels({}, {});
    m_sessionBar->setRecordEnabled(false);
}

// What the live session could not do (a processor, a calibration it could
// not read) is shown, never only logged: a calibration is never dropped
// without the operator knowing.
void MainWindow::reportSessionProblems()
{
    for (const auto& problem : m_session->takeProblems())
        reportProblem(this, {tr("Analysis not available"), tr("Part of the analysis cannot run on this device."),
                             QString::fromStdString(problem),
                             tr("The live view and recording go on; check the probe's profile and calibrations.")});
}

void MainWindow::updateStatus()
{
    if (!m_session) return;
    reportSessionProblems();
    const LinkCounters counters = linkCounters(m_session->stats(), m_session->source());
    m_devicePanel->showCounters(counters);
    m_status->showLink(counters);
    for (const std::string& problem : m_others->update())
        reportProblem(this, {tr("Device stopped"), tr("One device's part of the recording ended early."),
                             QString::fromStdString(problem), tr("The other devices record on.")});
    m_modeViews->update(*m_session);
    updateTimeBase();
    showDefectsOnTraces();
    const bool wasRecording = isRecording();
    if (const auto stopped = m_session->poll()) recordingEnded(*stopped);  // the disk stopped it
    m_handsFree->update();
    if (isRecording() != wasRecording) {  // a trigger started or ended one
        m_sessionBar->setRecording(isRecording());
        lockProfiles();
    }
    // A link that failed for good (another probe came back on the port, a
    // rate that is not the device's) records nothing more: the recording
    // ends with what came before, the operator is told why, and a new
    // session starts only when they connect and record again.
    if (isRecording() && m_session->stats().state == devices::AcquisitionState::Failed) stopRecording();
    // What the link noticed is in the record (an alarm) and told here.
    for (const auto& notice : m_session->takeLinkNotices()) {
        const QString text =
            tr("Device, at %1 s: %2").arg(fixedText(notice.time_s, 1), QString::fromStdString(notice.text));
        logProblem({tr("Device"), text, {}, {}});
        statusBar()->showMessage(text, 15000);
    }
    updateRecording();
}

// The panel's defects where they happened on the traces (which count
// stream time); another generation of the lists is a new panel.
void MainWindow::showDefectsOnTraces()
{
    const auto& lists = m_session->lists();
    const auto& defects = m_session->panelDefects();
    if (lists.generation != m_defectsGeneration) {
        m_defectsGeneration = lists.generation;
        m_plot->clearEvents();
        m_defectsOnTraces = 0;
    }
    for (; m_defectsOnTraces < defects.size(); ++m_defectsOnTraces)
        m_plot->addEvent(lists.origin_s + defects[m_defectsOnTraces].start_s,
                         orderText(defects[m_defectsOnTraces].direction));
}

// One clock on every plot: the recording's while recording (as the
// markers, dialogs and the stored session read it), else since connect.
void MainWindow::updateTimeBase()
{
    const auto origin = m_session->recordingOrigin_s();
    const QString label = origin ? tr("Recording time (s)") : tr("Time since connect (s)");
    for (LivePlotWidget* plot : allPlots()) plot->setTimeOrigin(origin.value_or(0.0), label);
    m_others->setTimeBase(m_session->source().hostClock(), origin.value_or(0.0), label);
}

// The window's plots move as one while paused, under one banner.
void MainWindow::linkPlots()
{
    for (LivePlotWidget* lanes : m_modeViews->lanes()) {
        lanes->setPausedBannerShown(false);
        lanes->setCompactTimeTitle(true);  // the traces above name the clock
    }
    for (LivePlotWidget* from : allPlots())
        connect(from, &LivePlotWidget::userScrolled, this, [this, from](double start_s, double end_s) {
            for (LivePlotWidget* to : allPlots())
                if (to != from) to->followTimeRange(start_s, end_s);
        });
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Tactiscope"), aboutText());
}

}  // namespace tactiscope::ui
