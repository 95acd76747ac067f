// The workstation's main window: the session bar (what is inspected, the
// record button) on top, the live plot of the connected device in the
// centre, device, session and view menus, and a status bar with the device
// name, its state, the measured sample rate, the samples received and what
// is being recorded.
//
// The window owns the device's Acquisition (a worker thread) and the
// LiveBuffer between them; it only reads counters and buffered samples, so
// the GUI never waits on the device.
#pragma once

#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"
#include "devices/BlockSource.h"
#include "devices/ReconnectingSource.h"

#include <QMainWindow>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

class QDockWidget;
class QLabel;
class QStackedWidget;

namespace tactiscope::devices {
class Acquisition;
}
namespace tactiscope::core {
class LiveBuffer;
class SinkSlot;
}  // namespace tactiscope::core
namespace tactiscope::devices::simulator {
class LoadRig;
}
namespace tactiscope::core::storage {
class Recorder;
class RecordingTap;
}  // namespace tactiscope::core::storage
namespace tactiscope::core::detector {
class LiveDetection;
}  // namespace tactiscope::core::detector
namespace tactiscope::core::compliance {
class LivePalpation;
}  // namespace tactiscope::core::compliance
namespace tactiscope::core::capacitive {
class LiveCapacitive;
}  // namespace tactiscope::core::capacitive

namespace tactiscope::ui {

class CapacitiveView;
class DevicePanel;
class LivePlotWidget;
class PalpationView;
class RawConsole;
struct SourceRequest;
class PanelScanView;
class SensorProfileDialog;
class SessionBar;
class SessionBrowser;
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
    bool isConnected() const { return m_acquisition != nullptr; }
    bool isConnecting() const { return m_connectingLabel.has_value(); }

    LivePlotWidget* livePlot() const { return m_plot; }
    PanelScanView* panelScanView() const { return m_panelScan; }
    PalpationView* palpationView() const { return m_palpationView; }
    CapacitiveView* capacitiveView() const { return m_capacitiveView; }
    DevicePanel* devicePanel() const { return m_devicePanel; }

    // Recording: into the session store at storePath() (remembered across
    // runs), with the session bar's metadata and the device's identity.
    // Failures are shown without stopping the acquisition; start returns
    // whether recording started.
    void setStorePath(const QString& path);
    QString storePath() const { return m_storePath; }
    bool startRecording();
    void stopRecording();
    bool isRecording() const { return m_recorder != nullptr; }
    // "panel-scan", "palpation" or "capacitive"; false for another name.
    bool setMode(const QString& mode);
    // Reports, once, sessions of the store that a crash cut short.
    void reportInterruptedSessions();
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

private:
    void createMenus();
    // A simulator, an emulator behind a pty, or a port, as the device panel asks.
    void connectRequest(const SourceRequest& request);
    void finishConnecting(std::uint64_t attempt, std::unique_ptr<devices::BlockSource> source, const QString& error);
    void createStatusBar();
    // The traces and every mode view's lanes.
    std::vector<LivePlotWidget*> allPlots() const;
    void updateStatus();
    void showAbout();
    void chooseStore();
    void toggleRecording();
    void updateRecording();
    void showProblem(const QString& title, const QString& text, const QString& detail,
                     const QString& objectName = QStringLiteral("problemBox"));
    void restoreSettings();
    void showModeView();
    void showModeXY(const QWidget* view);
    void takeDetectorEvents();
    void addMarker(double time_s, const QString& note);
    core::sensors::SensorProfile modeProfile(const std::string& mode);
    // Rebuilds the mode's processor on its newly chosen profile.
    void applyProfile(const QString& mode);
    void lockProfiles();  // while recording
    void attachDetection(const std::vector<std::size_t>& strain, double rate_hz);
    void attachPalpation(const std::vector<core::ChannelDescriptor>& channels, double rate_hz);
    void takePalpationReadings();
    void attachCapacitive(const std::vector<core::ChannelDescriptor>& channels, double rate_hz);
    // A calibration wizard on the connected device ("gauge" or "capacitive").
    void calibrate(const QString& which);
    void connectSimulator(const std::string& scenario);
    void linkCalibration(std::int64_t session, std::int64_t calibration);
    void tare();  // the visible mode's zero
    void askVerdict(std::int64_t session, double end_s, int defects, const QString& verdict);
    void saveSettings() const;

    LivePlotWidget* m_plot = nullptr;
    SessionBar* m_sessionBar = nullptr;
    PanelScanView* m_panelScan = nullptr;
    PalpationView* m_palpationView = nullptr;
    CapacitiveView* m_capacitiveView = nullptr;
    QStackedWidget* m_modeViews = nullptr;  // the mode's view under the traces
    DevicePanel* m_devicePanel = nullptr;
    QDockWidget* m_deviceDock = nullptr;
    XYPlotWidget* m_xyPlot = nullptr;
    QDockWidget* m_xyDock = nullptr;
    RawConsole* m_rawConsole = nullptr;
    QDockWidget* m_consoleDock = nullptr;
    SensorProfileDialog* m_profileDialog = nullptr;  // created when first asked for
    QPointer<SessionBrowser> m_browser;              // of the current store, while open
    QLabel* m_recordingLabel = nullptr;
    QLabel* m_deviceLabel = nullptr;
    QLabel* m_linkLabel = nullptr;  // state, rate and losses in one line
    QTimer m_statusTimer;
    std::unique_ptr<devices::Acquisition> m_acquisition;
    std::shared_ptr<core::storage::RecordingTap> m_tap;              // on every acquisition
    std::shared_ptr<core::detector::LiveDetection> m_detection;      // when the probe has two strain channels
    std::shared_ptr<core::compliance::LivePalpation> m_palpation;    // when it is a compliance probe
    std::shared_ptr<core::capacitive::LiveCapacitive> m_capacitive;  // when it has a capacitance channel
    // Where those two sit on the acquisition: a new profile swaps them live.
    std::shared_ptr<core::SinkSlot> m_palpationSlot;
    std::shared_ptr<core::SinkSlot> m_capacitiveSlot;
    // The calibrations each mode's processor reads with ("palpation": the
    // beams' gauge factors, "capacitive": C0 and sensitivity), stored with
    // every session recorded in that mode.
    std::map<std::string, std::vector<core::storage::StoredCalibration>> m_modeCalibrations;
    std::shared_ptr<core::LiveBuffer> m_buffer;              // every channel, for the display and the wizards
    std::shared_ptr<devices::simulator::LoadRig> m_loadRig;  // when the simulator is a calibration rig
    std::shared_ptr<core::storage::Recorder> m_recorder;     // while recording
    QString m_storePath;
    std::map<std::string, std::string> m_modeProfiles;  // mode → JSON of the profile its view uses
    std::optional<QString> m_connectingLabel;
    std::uint64_t m_connectAttempt = 0;  // a newer attempt or a disconnect drops older results
    // One per connect attempt, so a new attempt never waits for an old
    // handshake; declared last: joined before the members they report to go.
    std::vector<std::jthread> m_connectors;
};

}  // namespace tactiscope::ui
