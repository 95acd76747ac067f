// ConnectDialog: layout, discovery refresh and the request it returns.
#include "ui/ConnectDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QIntValidator>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

constexpr int kDefaultBaud = 921600;  // what TSP/1 probes use (docs/protocol.md)

}  // namespace

ConnectDialog::ConnectDialog(QWidget* parent)
    : QDialog(parent),
      m_list(new QListWidget(this)),
      m_listHint(new QLabel(this)),
      m_path(new QLineEdit(this)),
      m_protocol(new QComboBox(this)),
      m_baud(new QComboBox(this)),
      m_textRate(new QDoubleSpinBox(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Connect to device"));
    m_list->setObjectName(QStringLiteral("deviceList"));
    m_path->setObjectName(QStringLiteral("pathEdit"));
    m_protocol->setObjectName(QStringLiteral("protocolBox"));
    m_baud->setObjectName(QStringLiteral("baudBox"));
    m_textRate->setObjectName(QStringLiteral("textRateBox"));

    m_listHint->setWordWrap(true);
    m_listHint->setStyleSheet(QStringLiteral("color: palette(placeholder-text);"));
    m_path->setPlaceholderText(tr("/dev/ttyACM0, or an emulator link such as /tmp/probe"));
    m_protocol->addItem(tr("TSP/1 binary frames"), static_cast<int>(devices::WireProtocol::Binary));
    m_protocol->addItem(tr("Text lines (Arduino Serial Plotter)"), static_cast<int>(devices::WireProtocol::Text));
    m_baud->setEditable(true);
    m_baud->setValidator(new QIntValidator(50, 4'000'000, m_baud));
    for (const int baud : {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
        m_baud->addItem(QString::number(baud));
    m_baud->setCurrentText(QString::number(kDefaultBaud));
    // 0 means "estimate": the text protocol carries no rate (docs/protocol.md).
    m_textRate->setRange(0.0, 100'000.0);
    m_textRate->setDecimals(1);
    m_textRate->setSuffix(tr(" Hz"));
    m_textRate->setSpecialValueText(tr("estimate from arrival times"));

    auto* refreshButton = new QPushButton(tr("&Refresh"), this);
    m_connectButton = m_buttons->addButton(tr("&Connect"), QDialogButtonBox::AcceptRole);
    m_connectButton->setDefault(true);

    auto* listHeader = new QHBoxLayout;
    listHeader->addWidget(new QLabel(tr("Devices found:"), this), 1);
    listHeader->addWidget(refreshButton);

    auto* form = new QFormLayout;
    form->addRow(tr("&Port:"), m_path);
    form->addRow(tr("Pro&tocol:"), m_protocol);
    form->addRow(tr("&Baud rate:"), m_baud);
    form->addRow(tr("&Sample rate:"), m_textRate);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(listHeader);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_listHint);
    layout->addSpacing(8);
    layout->addLayout(form);
    layout->addWidget(m_buttons);
    resize(560, 420);

    connect(refreshButton, &QPushButton::clicked, this, &ConnectDialog::refresh);
    connect(m_list, &QListWidget::currentRowChanged, this, &ConnectDialog::selectDevice);
    connect(m_list, &QListWidget::itemDoubleClicked, this, &QDialog::accept);
    connect(m_path, &QLineEdit::textChanged, this, &ConnectDialog::updateEnabled);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ConnectDialog::updateEnabled);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    refresh();
}

void ConnectDialog::refresh()
{
    const devices::Discovery found = devices::discoverDevices();
    m_discovered = found.devices;
    m_list->clear();
    for (const auto& device : m_discovered) {
        QString text = QStringLiteral("%1 — %2").arg(QString::fromStdString(device.path),
                                                     QString::fromStdString(device.description));
        if (!device.usbSerialNumber.empty())
            text += tr(", serial %1").arg(QString::fromStdString(device.usbSerialNumber));
        m_list->addItem(text);
    }
    QString hint = m_discovered.empty()
                       ? tr("No serial port or HID device found. Plug the probe in and refresh, or type its "
                            "path below (the emulator's link, for example).")
                       : tr("Reconnects to the same device by its USB serial number after an unplug.");
    if (!found.hidError.empty())
        hint += QLatin1Char(' ') + tr("HID devices unavailable: %1").arg(QString::fromStdString(found.hidError));
    m_listHint->setText(hint);
    updateEnabled();
}

void ConnectDialog::selectDevice()
{
    const int row = m_list->currentRow();
    if (row < 0 || row >= static_cast<int>(m_discovered.size())) return;
    const auto& device = m_discovered[static_cast<std::size_t>(row)];
    m_path->setText(QString::fromStdString(device.path));
    if (device.bus == devices::DeviceBus::Hid) m_protocol->setCurrentIndex(0);  // HID carries TSP/1 only
}

void ConnectDialog::setPath(const QString& path)
{
    m_path->setText(path);
}

void ConnectDialog::updateEnabled()
{
    const bool text = m_protocol->currentData().toInt() == static_cast<int>(devices::WireProtocol::Text);
    m_textRate->setEnabled(text);
    m_connectButton->setEnabled(!m_path->text().trimmed().isEmpty());
}

ConnectRequest ConnectDialog::request() const
{
    ConnectRequest request;
    const std::string path = m_path->text().trimmed().toStdString();
    request.device = {devices::DeviceBus::Serial, path, {}, path};
    for (const auto& device : m_discovered) {
        if (device.path == path) request.device = device;  // keeps the USB serial number for reconnecting
    }
    request.baud = m_baud->currentText().toInt();
    if (request.baud <= 0) request.baud = kDefaultBaud;
    request.options.protocol = static_cast<devices::WireProtocol>(m_protocol->currentData().toInt());
    if (m_textRate->value() > 0.0) request.options.textRate_hz = m_textRate->value();
    return request;
}

}  // namespace tactiscope::ui
