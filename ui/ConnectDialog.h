// "Connect to device": the discovered serial ports and HID devices, a path
// field for anything not discovered (an emulator link, a port libserialport
// does not list), and the link settings: protocol, baud rate and, for the
// text protocol, the sample rate.
#pragma once

#include "devices/DeviceDiscovery.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace tactiscope::ui {

struct ConnectRequest {
    devices::DiscoveredDevice device;
    int baud = 921600;
    devices::PortSourceOptions options;
};

class ConnectDialog : public QDialog {
    Q_OBJECT

public:
    explicit ConnectDialog(QWidget* parent = nullptr);

    // What the user chose; meaningful after accept().
    ConnectRequest request() const;
    // Fills the path field, e.g. from the command line or a test.
    void setPath(const QString& path);

private:
    void refresh();
    void selectDevice();
    void updateEnabled();

    std::vector<devices::DiscoveredDevice> m_discovered;
    QListWidget* m_list = nullptr;
    QLabel* m_listHint = nullptr;
    QLineEdit* m_path = nullptr;
    QComboBox* m_protocol = nullptr;
    QComboBox* m_baud = nullptr;
    QDoubleSpinBox* m_textRate = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QPushButton* m_connectButton = nullptr;
};

}  // namespace tactiscope::ui
