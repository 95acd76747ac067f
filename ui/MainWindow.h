// The workstation's main window: the session bar (what is inspected, the
// record button) on top, the live plot of the connected device in the
// centre, device, session and view menus, and a status bar with the device
// name, its state, the measured sample rate, the samples received and what
// is being recorded.
//
// The window owns one live-session controller (devices/session/LiveSession)
// per connected device and only wires widgets to it: the controller runs the
// acquisition, the mode processors and the recording, and decides what is
// allowed; the window shows what it says, so the GUI never waits on the
// device. Its writes to the store go through one store worker, so it never
// waits on SQLite either; connecting, reviewing, calibrating and telling
// problems are in modules of their own (DeviceConnector, ReviewWindows,
// CalibrationWizards, ProblemReport).
#pragma once

#include "core/Vocabulary.h"
#include "core/modes/ChannelRoles.h"
#include "core/storage/SessionStore.h"
#include "devices/BlockSource.h"
#include "devices/ReconnectingSource.h"

#include <QMainWindow>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QDockWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}
namespace tactiscope::devices::simulator {
class LoadRig;
}
namespace tactiscope::devices::session {
class LiveSession;
class SessionOfDevices;
struct RecordingSummary;
}  // namespace tactiscope::devices::session

namespace tactiscope::ui {

class DeviceConnector;
class OtherDevices;
class DevicePanel;
class HandsFreeControl;
class WatchBanner;
class LivePlotWidget;
class ModeViews;
class RawConsole;
class CentralStoreLink;
class ReviewWindows;
class LiveModeView;
class SensorProfileDialog;
class SessionBar;
class SessionBrowser;
class StatusLine;
class XYPlotWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Disconnects any current device, then streams from `source`.
    void connectSource(std::unique_ptr<devices::BlockSource> source);
    // Opens a device on a worker thread (the handshake can take seconds) and
    // connects it when it answers; a failure is shown, never thrown. The
    // device is reopened automatically after an unplug.
    void connectDevice(const QString& label, devices::ReconnectingSource::Opener opener);
    void disconnectSource();
    bool isConnected() const { return m_session != nullptr; }
    bool isConnecting() const;

    LivePlotWidget* livePlot() const { return m_plot; }
    // The live view of `mode` (ui/modes/ModeUi.h); null for a mode without one.
    LiveModeView* modeView(core::Mode mode) const;
    DevicePanel* devicePanel() const { return m_devicePanel; }
    // The devices recorded with the connected one (View ▸ Other devices).
    OtherDevices* otherDevices() const { return m_others; }

    // Recording: into the session store at storePath() (remembered across
    // runs), with the session bar's metadata and the device's identity.
    // Failures are shown without stopping the acquisition; start returns
    // whether recording started.
    // Makes `path` the session store when it is one (or is not there yet,
    // for the first recording to create), for the live session too (its
    // next recording, its calibrations); else says why and keeps the old.
    // Refused while recording.
    bool useStore(const QString& path);
    // The path alone, unchecked: at start, before a device is connected.
    void setStorePath(const QString& path);
    QString storePath() const { return m_storePath; }
    bool startRecording();
    void stopRecording();
    bool isRecording() const;
    // The session's mode; false (and a message naming the channels it
    // needs) when the connected device cannot feed it.
    bool setMode(core::Mode mode);
    core::Mode mode() const;
    // The controller of the connected device; null when none is.
    devices::session::LiveSession* liveSession() const { return m_session.get(); }
    // Reports a damaged or unreadable store at once, and, once, the
    // sessions of the store that a crash cut short.
    void checkStore();
    // A timestamped marker in the session being recorded.
    void markEvent(const QString& note = {});
    // Takes the time now and asks for the note without blocking.
    void markEventWithNote();
    // The sensor-profile dialog (non-modal), opened on the current mode.
    SensorProfileDialog* showProfiles();
    // The session browser of the store (non-modal, one at a time).
    SessionBrowser* showSessionBrowser();
    // A review window for each session (an open one is raised); failures
    // are shown.
    void reviewSessions(const std::vector<std::int64_t>& sessions);

protected:
    void closeEvent(QCloseEvent* event) override;
    void askToStopBeforeQuitting();

private:
    void createMenus();
    // The traces and every mode view's lanes.
    std::vector<LivePlotWidget*> allPlots() const;
    void updateStatus();
    void showAbout();
    void chooseStore();
    void toggleRecording();
    void updateRecording();
    void restoreSettings();
    // The bar's mode changed: the controller agrees, or the bar goes back.
    void modeChosen();
    void showModeView();
    void addMarker(double time_s, const QString& note);
    void updateTimeBase();
    void showDefectsOnTraces();
    void reportSessionProblems();
    void linkPlots();
    // The mode's processor reads the newly chosen profile.
    void applyProfile(const QString& mode);
    void showMode(core::Mode mode);  // the views of a mode, with its probe and calibrations
    void setRoles(const core::RoleAssignment& roles);
    void lockProfiles();  // while recording
    // The mode's calibration wizard on the connected device.
    void calibrate(core::Mode mode);
    void tare();  // the mode's zero, when its rule allows
    // A recording ended: by a stop, the disk, the link, or (`triggered`)
    // its trigger, after which no verdict is asked: the line goes on.
    void recordingEnded(const devices::session::RecordingSummary& summary, bool triggered = false);
    // With other devices: each records its part of one session.
    bool startRecordingDevices(const core::storage::SessionMetadata& metadata);
    // Their parts ended with the window's device's; the summary names the session.
    devices::session::RecordingSummary endRecordingDevices(devices::session::RecordingSummary summary);
    void addOtherDevice(std::unique_ptr<devices::BlockSource> source);
    // The connected device's name in a session of several.
    std::string deviceName() const;
    void saveSettings() const;

    LivePlotWidget* m_plot = nullptr;
    SessionBar* m_sessionBar = nullptr;
    WatchBanner* m_watchBanner = nullptr;     // the trigger's state and the alarms, above the traces
    HandsFreeControl* m_handsFree = nullptr;  // triggers and limit alarms
    ModeViews* m_modeViews = nullptr;         // the mode's view under the traces
    DevicePanel* m_devicePanel = nullptr;
    ReviewWindows* m_review = nullptr;      // the browser and review windows of the store
    CentralStoreLink* m_central = nullptr;  // sends the sessions on to the site's central store
    QDockWidget* m_deviceDock = nullptr;
    XYPlotWidget* m_xyPlot = nullptr;
    QDockWidget* m_xyDock = nullptr;
    RawConsole* m_rawConsole = nullptr;
    QDockWidget* m_consoleDock = nullptr;
    SensorProfileDialog* m_profileDialog = nullptr;  // created when first asked for
    StatusLine* m_status = nullptr;
    QTimer m_statusTimer;
    std::uint64_t m_defectsGeneration = 0;                     // of the session's lists drawn on m_plot
    std::size_t m_defectsOnTraces = 0;                         // of the session's panel defects, drawn on m_plot
    std::unique_ptr<devices::session::LiveSession> m_session;  // of the connected device
    std::shared_ptr<devices::simulator::LoadRig> m_loadRig;    // when the simulator is a calibration rig
    QString m_storePath;
    std::shared_ptr<core::storage::StoreWorker> m_store;  // the window's connection to the store, off its thread
    DeviceConnector* m_connector = nullptr;
    OtherDevices* m_others = nullptr;
    QDockWidget* m_othersDock = nullptr;
    DeviceConnector* m_adder = nullptr;                                    // opens the other devices
    std::unique_ptr<devices::session::SessionOfDevices> m_devicesSession;  // while recording with other devices
};

}  // namespace tactiscope::ui
