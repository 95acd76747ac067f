// DevicePanel: the source list, link settings, connect buttons and counters.
#include "ui/device/DevicePanel.h"

#include "ui/device/ChannelRolesBox.h"

#include "core/UnitScale.h"
#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/LoadCellScenario.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "ui/common/NumberText.h"
#include "ui/device/LinkStatus.h"
#include "ui/live/LiveStation.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIntValidator>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

constexpr int kDefaultBaud = 921600;  // what TSP/1 probes use (docs/protocol.md)
constexpr int kKindRole = Qt::UserRole;
constexpr int kIdRole = Qt::UserRole + 1;  // scenario id, or index into the discovered devices

QString scenarioTitle(const std::string& id)
{
    if (id == devices::simulator::kPanelScanScenario) return DevicePanel::tr("Panel scan — two strain cantilevers");
    if (id == devices::simulator::kPanelLineScenario) return DevicePanel::tr("Panel line — one stroke per panel");
    if (id == devices::simulator::kPanelRestScenario) return DevicePanel::tr("Panel probe — at rest");
    if (id == devices::simulator::kPalpationScenario) return DevicePanel::tr("Palpation — compliance probe");
    if (id == "capacitive-weights") return DevicePanel::tr("Capacitive beam — weights");
    if (id == "gauge-calibration") return DevicePanel::tr("Gauge-factor rig — stiff beam");
    if (id == "gauge-calibration-soft") return DevicePanel::tr("Gauge-factor rig — soft beam");
    if (id == "capacitive-calibration") return DevicePanel::tr("Capacitive beam — calibration rig");
    if (id == devices::simulator::kCapacitiveOverloadScenario) return DevicePanel::tr("Capacitive beam — overloaded");
    if (id == devices::simulator::kLoadCellScenario) return DevicePanel::tr("Load cell — a reference force");
    return QString::fromStdString(id);
}

QString count(std::uint64_t n)
{
    return QLocale().toString(static_cast<qulonglong>(n));
}

}  // namespace

DevicePanel::DevicePanel(QWidget* parent)
    : QWidget(parent),
      m_sources(new QTreeWidget(this)),
      m_hint(new QLabel(this)),
      m_path(new QLineEdit(this)),
      m_protocol(new QComboBox(this)),
      m_baud(new QComboBox(this)),
      m_textRate(new QDoubleSpinBox(this)),
      m_textUnits(new QLineEdit(this)),
      m_connect(new QPushButton(tr("&Connect"), this)),
      m_disconnect(new QPushButton(tr("&Disconnect"), this)),
      m_connectedTo(new QLabel(this))
{
    m_sources->setObjectName(QStringLiteral("sourceTree"));
    m_path->setObjectName(QStringLiteral("pathEdit"));
    m_protocol->setObjectName(QStringLiteral("protocolBox"));
    m_baud->setObjectName(QStringLiteral("baudBox"));
    m_textRate->setObjectName(QStringLiteral("textRateBox"));
    m_textUnits->setObjectName(QStringLiteral("textUnitsEdit"));
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_disconnect->setObjectName(QStringLiteral("disconnectButton"));
    m_connectedTo->setObjectName(QStringLiteral("connectedToLabel"));

    m_sources->setHeaderHidden(true);
    m_sources->setRootIsDecorated(false);
    m_sources->setIndentation(12);
    m_sources->setUniformRowHeights(true);
    m_hint->setWordWrap(true);
    m_hint->setStyleSheet(QStringLiteral("color: palette(placeholder-text);"));
    m_path->setPlaceholderText(tr("/dev/ttyACM0 or a link such as /tmp/probe"));
    m_protocol->addItem(tr("TSP/1 binary frames"), static_cast<int>(devices::WireProtocol::Binary));
    m_protocol->addItem(tr("Text lines (any board)"), static_cast<int>(devices::WireProtocol::Text));
    m_baud->setEditable(true);
    m_baud->setValidator(new QIntValidator(50, 4'000'000, m_baud));
    for (const int baud : {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
        m_baud->addItem(QString::number(baud));
    m_baud->setCurrentText(QString::number(kDefaultBaud));
    // 0 means "time it": a text board states no rate (docs/protocol.md).
    m_textRate->setRange(0.0, 100'000.0);
    m_textRate->setDecimals(1);
    m_textRate->setSuffix(tr(" Hz"));
    m_textRate->setSpecialValueText(tr("time it"));
    // A board's label may carry its unit ("a[µε]:12"); these are for the
    // plain numbers of a board one cannot change.
    m_textUnits->setPlaceholderText(tr("e.g. a=µε, b=µε"));

    // Large buttons: this panel is used with gloves on.
    for (QPushButton* button : {m_connect, m_disconnect}) button->setMinimumHeight(40);
    m_connect->setDefault(true);
    m_connect->setToolTip(tr("Connect to the selected source (double-click works too)"));
    auto* refreshButton = new QPushButton(tr("&Refresh"), this);
    refreshButton->setToolTip(tr("Look for serial ports and HID devices again"));
    m_add = new QPushButton(tr("Add to the &session"), this);
    m_add->setObjectName(QStringLiteral("addDeviceButton"));
    m_add->setToolTip(tr("Connect the selected source as another device, recorded with the connected one into one "
                         "session, each on its own clock (View ▸ Other devices)"));

    auto* sourcesBox = new QGroupBox(tr("Sources"), this);
    auto* sourcesLayout = new QVBoxLayout(sourcesBox);
    sourcesLayout->addWidget(m_sources, 1);
    sourcesLayout->addWidget(m_hint);
    auto* link = new QFormLayout;
    link->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    link->addRow(tr("&Port:"), m_path);
    link->addRow(tr("Pro&tocol:"), m_protocol);
    link->addRow(tr("&Baud:"), m_baud);
    link->addRow(tr("&Rate:"), m_textRate);
    link->addRow(tr("U&nits:"), m_textUnits);
    sourcesLayout->addLayout(link);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(refreshButton);
    buttons->addStretch(1);
    buttons->addWidget(m_add);
    sourcesLayout->addLayout(buttons);
    auto* connectRow = new QHBoxLayout;
    connectRow->addWidget(m_connect, 1);
    connectRow->addWidget(m_disconnect, 1);
    sourcesLayout->addLayout(connectRow);

    auto* countersBox = new QGroupBox(tr("Link"), this);
    auto* counters = new QFormLayout(countersBox);
    counters->addRow(m_connectedTo);
    m_connectedTo->setWordWrap(true);
    m_state = addCounter(counters, tr("State"), "stateLabel");
    QFont stateFont = m_state->font();
    stateFont.setBold(true);
    stateFont.setPointSizeF(stateFont.pointSizeF() * 1.2);
    m_state->setFont(stateFont);
    m_rate = addCounter(counters, tr("Rate"), "rateLabel");
    // "1,000.0 Hz (nominal 1,000 Hz)" wraps in a narrow dock rather than
    // being cut or widening the panel as the measurement comes.
    m_rate->setWordWrap(true);
    m_samples = addCounter(counters, tr("Samples"), "samplesLabel");
    m_lost = addCounter(counters, tr("Lost"), "lostLabel");
    m_crc = addCounter(counters, tr("CRC errors"), "crcLabel");
    m_resyncs = addCounter(counters, tr("Resyncs"), "resyncLabel");
    m_reconnections = addCounter(counters, tr("Reconnects"), "reconnectLabel");

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    m_roles = new ChannelRolesBox(this);
    // The sources keep their height and the hint room for three lines:
    // the Port field stays where it is as the channel roles come and go
    // and the hint changes. Spare height goes below the counters.
    m_hint->setMinimumHeight(3 * m_hint->fontMetrics().lineSpacing());
    m_hint->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    layout->addWidget(sourcesBox);
    layout->addWidget(m_roles);
    layout->addWidget(countersBox);
    layout->addStretch(1);

    connect(refreshButton, &QPushButton::clicked, this, &DevicePanel::refresh);
    connect(m_sources, &QTreeWidget::currentItemChanged, this, &DevicePanel::selectionChanged);
    connect(m_sources, &QTreeWidget::itemDoubleClicked, this, &DevicePanel::requestConnect);
    connect(m_path, &QLineEdit::textEdited, this, [this] {
        // A typed path is a port of its own, whatever was selected.
        m_sources->setCurrentItem(nullptr);
        updateEnabled();
    });
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &DevicePanel::updateEnabled);
    connect(m_textUnits, &QLineEdit::textChanged, this, &DevicePanel::updateEnabled);
    connect(m_connect, &QPushButton::clicked, this, &DevicePanel::requestConnect);
    connect(m_add, &QPushButton::clicked, this, [this] {
        if (const auto choice = request()) emit addRequested(*choice);
    });
    connect(m_disconnect, &QPushButton::clicked, this, &DevicePanel::disconnectRequested);
    refresh();
    clearCounters();
}

QLabel* DevicePanel::addCounter(QFormLayout* form, const QString& caption, const char* objectName)
{
    auto* value = new QLabel(this);
    value->setObjectName(QString::fromLatin1(objectName));
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Room for a long count from the start: a counter that grows must not
    // widen the dock and squeeze the traces and the mode's view beside it.
    value->setMinimumWidth(value->fontMetrics().horizontalAdvance(QStringLiteral("Reconnecting… 000 000 000")));
    value->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    form->addRow(caption + QLatin1Char(':'), value);
    return value;
}

void DevicePanel::refresh()
{
    const devices::Discovery found = devices::discoverDevices();
    m_discovered = found.devices;
    const QString selectedPath = m_path->text();
    m_sources->clear();
    const auto group = [this](const QString& title) {
        auto* item = new QTreeWidgetItem(m_sources, {title});
        item->setFlags(Qt::ItemIsEnabled);  // a heading, not a choice
        QFont bold = item->font(0);
        bold.setBold(true);
        item->setFont(0, bold);
        item->setExpanded(true);
        return item;
    };
    const auto choice = [](QTreeWidgetItem* parent, const QString& text, SourceKind kind, const QVariant& id) {
        auto* item = new QTreeWidgetItem(parent, {text});
        item->setData(0, kKindRole, static_cast<int>(kind));
        item->setData(0, kIdRole, id);
        return item;
    };
    QTreeWidgetItem* simulator = group(tr("Simulator"));
    QTreeWidgetItem* emulator = group(tr("Emulator (serial path, no hardware)"));
    for (const std::string& id : devices::simulator::scenarioIds()) {
        choice(simulator, scenarioTitle(id), SourceKind::Simulator, QString::fromStdString(id));
        // Told apart wherever the choice is named again (the status line).
        choice(emulator, tr("%1 (emulated port)").arg(scenarioTitle(id)), SourceKind::Emulator,
               QString::fromStdString(id))
            ->setToolTip(0, tr("The same probe behind a pseudo-terminal, through the serial path a real probe takes"));
    }
    QTreeWidgetItem* ports = group(tr("Serial ports and HID devices"));
    for (std::size_t i = 0; i < m_discovered.size(); ++i) {
        const auto& device = m_discovered[i];
        QString text = QStringLiteral("%1 — %2").arg(QString::fromStdString(device.path),
                                                     QString::fromStdString(device.description));
        QTreeWidgetItem* item = choice(ports, text, SourceKind::Port, static_cast<qulonglong>(i));
        if (!device.usbSerialNumber.empty())
            item->setToolTip(0, tr("USB serial number %1").arg(QString::fromStdString(device.usbSerialNumber)));
    }
    QString hint = m_discovered.empty() ? tr("No serial port or HID device found: plug the probe in and refresh, "
                                             "or type its path below.")
                                        : tr("A port reconnects to the same probe by its USB serial number.");
    if (!found.hidError.empty())
        hint += QLatin1Char(' ') + tr("HID devices unavailable: %1").arg(QString::fromStdString(found.hidError));
    m_hint->setText(hint);
    m_path->setText(selectedPath);
    updateEnabled();
}

void DevicePanel::selectionChanged()
{
    // A simulated or emulated probe speaks TSP/1 unless told otherwise
    // after it is chosen: a text protocol left from a board is no default.
    if (selectedKind() == SourceKind::Simulator || selectedKind() == SourceKind::Emulator)
        m_protocol->setCurrentIndex(0);
    if (selectedKind() == SourceKind::Port) {
        const auto& device = m_discovered[m_sources->currentItem()->data(0, kIdRole).toULongLong()];
        m_path->setText(QString::fromStdString(device.path));
        if (device.bus == devices::DeviceBus::Hid) m_protocol->setCurrentIndex(0);  // HID carries TSP/1 only
    }
    updateEnabled();
}

void DevicePanel::selectSimulator(const QString& scenario)
{
    const QTreeWidgetItem* simulator = m_sources->topLevelItem(0);
    for (int i = 0; i < simulator->childCount(); ++i) {
        if (simulator->child(i)->data(0, kIdRole).toString() == scenario)
            m_sources->setCurrentItem(simulator->child(i));
    }
}

void DevicePanel::setPath(const QString& path)
{
    m_sources->setCurrentItem(nullptr);
    m_path->setText(path);
    updateEnabled();
}

void DevicePanel::watch(LiveStation& station)
{
    connect(this, &DevicePanel::connectRequested, &station, &LiveStation::request);
    connect(this, &DevicePanel::addRequested, &station, &LiveStation::addDevice);
    connect(this, &DevicePanel::disconnectRequested, &station, &LiveStation::disconnectDevices);
    connect(&station, &LiveStation::connecting, this, &DevicePanel::setConnecting);
    connect(&station, &LiveStation::connectFailed, this, [this] {
        setConnected(false);
        clearCounters(tr("Connection failed"));
    });
    connect(&station, &LiveStation::connected, this, [this, &station] {
        const auto& live = *station.device();
        setConnected(true, QString::fromStdString(live.source().name()));
        showRoles(live);
    });
    connect(&station, &LiveStation::disconnected, this, [this] {
        setConnected(false);
        m_roles->setChannels({}, {});
    });
    connect(&station, &LiveStation::polled, this, [this, &station] {
        if (const auto* live = station.device()) showCounters(linkCounters(live->stats(), live->source()));
    });
    connect(&station, &LiveStation::recordingChanged, m_roles, &ChannelRolesBox::setLocked);
}

// The device's channels and their roles; open for a device that feeds no
// mode by itself (it starts in one that needs no roles), or was given roles.
void DevicePanel::showRoles(const devices::session::LiveSession& live)
{
    m_roles->setChannels(live.source().channels(), live.roles(),
                         core::definitionOf(live.declaredMode()).roles.empty() || !live.roles().empty());
}

std::optional<SourceRequest> DevicePanel::request() const
{
    SourceRequest request;
    request.options.protocol = static_cast<devices::WireProtocol>(m_protocol->currentData().toInt());
    if (m_textRate->value() > 0.0) request.options.textRate_hz = m_textRate->value();
    if (request.options.protocol == devices::WireProtocol::Text) {
        const auto units = givenUnits();
        if (!units) return std::nullopt;  // the field says why (updateEnabled)
        request.options.textUnits = *units;
    }
    request.baud = m_baud->currentText().toInt();
    if (request.baud <= 0) request.baud = kDefaultBaud;

    const auto kind = selectedKind();
    if (kind && *kind != SourceKind::Port) {
        request.kind = *kind;
        request.scenario = m_sources->currentItem()->data(0, kIdRole).toString().toStdString();
        return request;
    }
    const std::string path = m_path->text().trimmed().toStdString();
    if (path.empty()) return std::nullopt;
    request.kind = SourceKind::Port;
    request.device = {devices::DeviceBus::Serial, path, {}, path};
    for (const auto& device : m_discovered) {
        if (device.path == path) request.device = device;  // keeps the USB serial number for reconnecting
    }
    return request;
}

std::optional<SourceKind> DevicePanel::selectedKind() const
{
    const QTreeWidgetItem* item = m_sources->currentItem();
    const QVariant kind = item ? item->data(0, kKindRole) : QVariant();
    if (!kind.isValid()) return std::nullopt;  // nothing, or a heading
    return static_cast<SourceKind>(kind.toInt());
}

std::optional<core::UnitAssignment> DevicePanel::givenUnits(QString* problem) const
{
    try {
        return core::parseUnitAssignment(m_textUnits->text().toStdString());
    } catch (const std::invalid_argument& e) {
        if (problem) *problem = QString::fromStdString(e.what());
        return std::nullopt;
    }
}

void DevicePanel::updateEnabled()
{
    // The simulator has no link; the emulator has a protocol but no port.
    const auto kind = selectedKind();
    const bool simulator = kind == SourceKind::Simulator;
    const bool emulator = kind == SourceKind::Emulator;
    const bool text = m_protocol->currentData().toInt() == static_cast<int>(devices::WireProtocol::Text);
    m_path->setEnabled(!simulator && !emulator);
    m_protocol->setEnabled(!simulator);
    m_baud->setEnabled(!simulator && !emulator);
    m_textRate->setEnabled(!simulator && text);
    m_textUnits->setEnabled(!simulator && text);
    QString unitsProblem;
    givenUnits(&unitsProblem);
    const QString help = tr("Units of a text board's channels by name: NAME=UNIT, … Strain (strain, µε), force "
                            "(N, mN), length (m, mm) and capacitance (F, pF) feed the modes; a channel with no unit "
                            "is a plain number, recorded as it is.");
    // A list that cannot be read keeps Connect off, and says why.
    m_textUnits->setStyleSheet(unitsProblem.isEmpty() ? QString() : QStringLiteral("color: #b00020;"));
    m_textUnits->setToolTip(unitsProblem.isEmpty() ? help : tr("Cannot connect: %1\n\n%2").arg(unitsProblem, help));
    m_connect->setEnabled(request().has_value());
    m_disconnect->setEnabled(m_connected);
    // Another device joins a connected one; the emulator's link is the window's own.
    m_add->setEnabled(m_connected && request().has_value() && !emulator);
}

void DevicePanel::requestConnect()
{
    if (const auto choice = request()) emit connectRequested(*choice);
}

void DevicePanel::setConnecting(const QString& label)
{
    m_connectedTo->setText(tr("Connecting to %1…").arg(label));
    clearCounters(tr("Connecting…"));
    m_connected = true;  // a handshake can be cancelled by disconnecting
    updateEnabled();
}

void DevicePanel::setConnected(bool connected, const QString& name)
{
    m_connected = connected;
    m_connectedTo->setText(connected ? name : tr("Not connected"));
    if (!connected) clearCounters();
    updateEnabled();
}

void DevicePanel::clearCounters(const QString& state)
{
    m_state->setText(state.isEmpty() ? tr("—") : state);
    m_state->setStyleSheet(QString());
    for (QLabel* label : {m_rate, m_samples, m_lost, m_crc, m_resyncs, m_reconnections}) label->setText(tr("—"));
}

void DevicePanel::showCounters(const LinkCounters& counters)
{
    m_state->setText(counters.state);
    m_state->setStyleSheet(counters.healthy ? QStringLiteral("color: #2e7d32;") : QStringLiteral("color: #c62828;"));
    // A text board states no rate: the one its lines were timed at, with
    // its uncertainty, is what every time rests on.
    const QString nominal =
        !counters.nominalMeasured ? tr("nominal %1 Hz").arg(compactText(counters.nominalRate_hz, 6))
        : counters.nominalRateU_hz
            ? tr("timed %1 ± %2 Hz from its lines")
                  .arg(compactText(counters.nominalRate_hz, 7), compactText(*counters.nominalRateU_hz, 2))
            : tr("timed %1 Hz from its lines").arg(compactText(counters.nominalRate_hz, 7));
    m_rate->setText(counters.rate_hz ? tr("%1 Hz (%2)").arg(fixedText(*counters.rate_hz, 1), nominal)
                                     : tr("measuring… (%1)").arg(nominal));
    m_samples->setText(count(counters.samples));
    m_lost->setText(count(counters.samplesLost));
    // Any loss is worth a glance: red, not hidden among the other numbers.
    m_lost->setStyleSheet(counters.samplesLost > 0 ? QStringLiteral("color: #c62828;") : QString());
    const auto& decoder = counters.decoder;
    m_crc->setText(decoder ? count(decoder->crcErrors) : tr("— (no wire protocol)"));
    m_crc->setStyleSheet(decoder && decoder->crcErrors > 0 ? QStringLiteral("color: #c62828;") : QString());
    m_resyncs->setText(decoder ? count(decoder->resyncs) : tr("—"));
    m_reconnections->setText(count(counters.reconnections));
}

namespace {

// Keeps a scroll area as wide as its panel needs beside a vertical scroll
// bar, as the panel grows (a device's channel roles, a longer link name):
// set once, the general mode's roles cut the panel at its right edge.
class WidthFollower : public QObject {
public:
    WidthFollower(QScrollArea* scroll, QWidget* panel)
        : QObject(scroll),
          m_scroll(scroll),
          m_panel(panel)
    {
        panel->installEventFilter(this);
        follow();
    }

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == m_panel && event->type() == QEvent::LayoutRequest) follow();
        return false;
    }

private:
    void follow()
    {
        m_scroll->setMinimumWidth(m_panel->minimumSizeHint().width() +
                                  m_scroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 2);
    }

    QScrollArea* m_scroll;
    QWidget* m_panel;
};

}  // namespace

QWidget* scrollingPanel(DevicePanel* panel)
{
    auto* scroll = new QScrollArea(panel->parentWidget());
    scroll->setObjectName(QStringLiteral("devicePanelScroll"));
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // It only ever scrolls up and down.
    new WidthFollower(scroll, panel);
    return scroll;
}

}  // namespace tactiscope::ui
