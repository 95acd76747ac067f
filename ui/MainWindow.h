// The workstation's main window: the live plot of the connected device in
// the centre, device and view menus, and a status bar with the device name,
// its state, the measured sample rate and the samples received.
//
// The window owns the device's Acquisition (a worker thread) and the
// LiveBuffer between them; it only reads counters and buffered samples, so
// the GUI never waits on the device.
#pragma once

#include "devices/BlockSource.h"
#include "devices/ReconnectingSource.h"

#include <QMainWindow>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

class QLabel;

namespace tactiscope::devices {
class Acquisition;
}

namespace tactiscope::ui {

class LivePlotWidget;

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

private:
    void createMenus();
    void showConnectDialog();
    void finishConnecting(std::uint64_t attempt, std::unique_ptr<devices::BlockSource> source, const QString& error);
    void createStatusBar();
    void updateStatus();
    void showAbout();

    LivePlotWidget* m_plot = nullptr;
    QLabel* m_deviceLabel = nullptr;
    QLabel* m_stateLabel = nullptr;
    QLabel* m_rateLabel = nullptr;
    QLabel* m_samplesLabel = nullptr;
    QTimer m_statusTimer;
    std::unique_ptr<devices::Acquisition> m_acquisition;
    std::optional<QString> m_connectingLabel;
    std::uint64_t m_connectAttempt = 0;  // a newer attempt or a disconnect drops older results
    // One per connect attempt, so a new attempt never waits for an old
    // handshake; declared last: joined before the members they report to go.
    std::vector<std::jthread> m_connectors;
};

}  // namespace tactiscope::ui
