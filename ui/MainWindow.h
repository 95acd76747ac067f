// The workstation's main window: a shell around the live station
// (ui/live/LiveStation: the one pipeline every recording goes through).
// It keeps the frame (the session bar on top, the device's traces in the
// centre, the mode's view under them, the docks and the status bar), the
// menus, the settings, the store choice, the other windows (review,
// profiles, calibration) and the reactions that need a dialog (a problem,
// the verdict at a stop, the question before quitting while recording).
// The live widgets watch the station themselves; the window names no
// mode: each mode's parts are asked of its entry (ui/modes/ModeUi.h).
#pragma once

#include "core/Vocabulary.h"

#include <QMainWindow>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

class QDockWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}
namespace tactiscope::devices::session {
struct RecordingEnd;
}

namespace tactiscope::ui {

class CentralStoreLink;
class DevicePanel;
class HandsFreeControl;
class LiveHealth;
class LiveSpectrum;
class SignalControl;
class LiveModeView;
class LivePlotWidget;
class LiveMarkers;
class LiveProfiles;
class LiveStation;
class LiveTraces;
class ModeChoice;
class ModeViews;
class OtherDevices;
class QuitQuestion;
class RawConsole;
class ReviewWindows;
class SensorProfileDialog;
class SessionBar;
class SessionBrowser;
class StatusLine;
class WatchBanner;
class XYPlotWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // The live workflow: devices, recording, trigger (ui/live/LiveStation).
    LiveStation& station() const { return *m_station; }
    LivePlotWidget* livePlot() const { return m_plot; }
    // The live view of `mode` (ui/modes/ModeUi.h); null for a mode without one.
    LiveModeView* modeView(core::Mode mode) const;
    DevicePanel* devicePanel() const { return m_devicePanel; }
    // The devices recorded with the connected one (View ▸ Other devices).
    OtherDevices* otherDevices() const { return m_others; }

    // Makes `path` the session store when it is one (or is not there yet,
    // for the first recording to create), for the live devices too (their
    // next recording, their calibrations); else says why and keeps the old.
    // Refused while recording.
    bool useStore(const QString& path);
    // The path alone, unchecked: at start, before a device is connected.
    void setStorePath(const QString& path);
    QString storePath() const { return m_storePath; }
    // Recording into the store with the session bar's metadata; the site's
    // policy and the station may refuse (shown); start returns whether it
    // started.
    bool startRecording();
    void stopRecording();
    bool isRecording() const;
    // The session's mode; false (and a message naming the channels it
    // needs) when the connected device cannot feed it.
    bool setMode(core::Mode mode);
    core::Mode mode() const;
    // Reports a damaged or unreadable store at once, and, once, the
    // sessions of the store that a crash cut short.
    void checkStore();
    // The operator's markers in the session being recorded.
    LiveMarkers& markers() const { return *m_markers; }
    // The sensor-profile dialog (non-modal), opened on the current mode.
    SensorProfileDialog* showProfiles();
    // The session browser of the store (non-modal, one at a time).
    SessionBrowser* showSessionBrowser();
    // A review window for each session (an open one is raised); failures
    // are shown.
    void reviewSessions(const std::vector<std::int64_t>& sessions);

protected:
    void closeEvent(QCloseEvent* event) override;  // asks first while recording (QuitQuestion)

private:
    void buildFrame();
    void watchStation();
    void createMenus();
    void restoreSettings();
    void saveSettings() const;
    void chooseStore();
    void toggleRecording();
    void deviceConnected();
    void recordingEnded(const devices::session::RecordingEnd& end);
    void tare();  // the mode's zero, when its rule allows

    LiveStation* m_station = nullptr;
    LivePlotWidget* m_plot = nullptr;    // the device's traces
    LiveTraces* m_traces = nullptr;      // them and the mode views' lanes as one
    LiveMarkers* m_markers = nullptr;    // the operator's markers
    LiveProfiles* m_profiles = nullptr;  // the sensor-profile dialog
    ModeChoice* m_modes = nullptr;       // the bar's mode against the device's
    QuitQuestion* m_quit = nullptr;      // quitting while recording
    SessionBar* m_sessionBar = nullptr;
    WatchBanner* m_watchBanner = nullptr;     // the trigger's state and the alarms, above the traces
    HandsFreeControl* m_handsFree = nullptr;  // triggers and limit alarms
    SignalControl* m_signal = nullptr;        // filters and math channels
    LiveSpectrum* m_spectrum = nullptr;       // View ▸ Spectrum
    LiveHealth* m_health = nullptr;           // View ▸ Signal health
    ModeViews* m_modeViews = nullptr;         // the mode's view under the traces
    DevicePanel* m_devicePanel = nullptr;
    ReviewWindows* m_review = nullptr;      // the browser and review windows of the store
    CentralStoreLink* m_central = nullptr;  // sends the sessions on to the site's central store
    QDockWidget* m_deviceDock = nullptr;
    XYPlotWidget* m_xyPlot = nullptr;
    QDockWidget* m_xyDock = nullptr;
    RawConsole* m_rawConsole = nullptr;
    QDockWidget* m_consoleDock = nullptr;
    OtherDevices* m_others = nullptr;
    QDockWidget* m_othersDock = nullptr;
    StatusLine* m_status = nullptr;
    QString m_storePath;
    std::shared_ptr<core::storage::StoreWorker> m_store;  // the window's connection to the store, off its thread
};

}  // namespace tactiscope::ui
