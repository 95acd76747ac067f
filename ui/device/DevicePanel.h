// The device panel, docked beside the plots: every source a user can stream
// from in one list — the built-in simulator's scenarios, the same scenarios
// behind the probe emulator's pseudo-terminal (the whole serial path without
// hardware), and the serial ports and HID devices found — the link settings
// for a port, connect / disconnect, and the live counters of the connected
// device: state, measured rate, samples, samples lost, CRC errors, resyncs,
// reconnections; and the connected device's channel roles
// (ChannelRolesBox). The panel only asks; the live station connects
// (watch()), and the panel shows what it says.
#pragma once

#include "core/UnitScale.h"
#include "devices/DeviceDiscovery.h"

#include <QWidget>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QTreeWidget;

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class ChannelRolesBox;
class LiveStation;

enum class SourceKind { Simulator, Emulator, Port };

// What the user asked to connect to.
struct SourceRequest {
    SourceKind kind = SourceKind::Port;
    std::string scenario;              // simulator and emulator
    devices::DiscoveredDevice device;  // port: the device (path, USB serial number)
    int baud = 921600;
    devices::PortSourceOptions options;  // port and emulator: the wire protocol
};

// The counters the panel shows, gathered by the main window on its timer.
struct LinkCounters {
    QString state;
    bool healthy = true;  // false: lost, reconnecting or failed (drawn in red)
    std::optional<double> rate_hz;
    double nominalRate_hz = 0.0;
    // A rate this program measured (a text board's), with its uncertainty:
    // shown as measured, not as the device's word.
    bool nominalMeasured = false;
    std::optional<double> nominalRateU_hz;
    std::uint64_t samples = 0;
    std::uint64_t samplesLost = 0;
    std::optional<devices::protocol::DecoderCounters> decoder;  // sources with a wire protocol
    std::uint64_t reconnections = 0;
};

class DevicePanel : public QWidget {
    Q_OBJECT

public:
    explicit DevicePanel(QWidget* parent = nullptr);

    // Asks `station` to connect, add and disconnect, and shows its device:
    // connecting, connected, its counters each poll, its channels' roles
    // (locked while recording).
    void watch(LiveStation& station);

    // The current choice in the list and the link fields.
    std::optional<SourceRequest> request() const;
    // Types a port path (an emulator link, a port not discovered).
    void setPath(const QString& path);
    // Selects a simulator scenario, as a click would.
    void selectSimulator(const QString& scenario);

    void setConnected(bool connected, const QString& name = {});
    void setConnecting(const QString& label);
    void showCounters(const LinkCounters& counters);
    void clearCounters(const QString& state = {});
    ChannelRolesBox* rolesBox() const { return m_roles; }
    void showRoles(const devices::session::LiveSession& live);

public slots:
    void refresh();

signals:
    void connectRequested(const SourceRequest& request);
    // The choice as another device of the session, beside the connected one.
    void addRequested(const SourceRequest& request);
    void disconnectRequested();

private:
    std::optional<SourceKind> selectedKind() const;
    void selectionChanged();
    void updateEnabled();
    void requestConnect();
    QLabel* addCounter(QFormLayout* form, const QString& caption, const char* objectName);

    // The Units field's list; none, and why in `problem`, when it cannot be read.
    std::optional<core::UnitAssignment> givenUnits(QString* problem = nullptr) const;

    std::vector<devices::DiscoveredDevice> m_discovered;
    QTreeWidget* m_sources = nullptr;
    QLabel* m_hint = nullptr;
    ChannelRolesBox* m_roles = nullptr;
    QLineEdit* m_path = nullptr;
    QComboBox* m_protocol = nullptr;
    QComboBox* m_baud = nullptr;
    QDoubleSpinBox* m_textRate = nullptr;
    QLineEdit* m_textUnits = nullptr;  // "a=µε, b=µε": a text board's plain numbers' units
    QPushButton* m_connect = nullptr;
    QPushButton* m_disconnect = nullptr;
    QPushButton* m_add = nullptr;
    QLabel* m_connectedTo = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_rate = nullptr;
    QLabel* m_samples = nullptr;
    QLabel* m_lost = nullptr;
    QLabel* m_crc = nullptr;
    QLabel* m_resyncs = nullptr;
    QLabel* m_reconnections = nullptr;
    bool m_connected = false;
};

// The panel in a scroll area for its dock: on a short screen it scrolls
// rather than squeezes, so its Port field stays put as the channel roles
// and the link's name below it come and go.
QWidget* scrollingPanel(DevicePanel* panel);

}  // namespace tactiscope::ui
