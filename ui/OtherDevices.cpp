// OtherDevices: a LiveSession, a title, a link line and a live plot per
// added device, and their parts of a recording.
#include "ui/OtherDevices.h"

#include "devices/session/SessionOfDevices.h"
#include "ui/LinkStatus.h"
#include "ui/LivePlotWidget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {

OtherDevices::OtherDevices(QWidget* parent)
    : QWidget(parent),
      m_layout(new QVBoxLayout(this)),
      m_hint(new QLabel(this))
{
    setObjectName(QStringLiteral("otherDevices"));
    setMinimumWidth(380);  // a device's name on one line, and a trace beside its axis
    m_hint->setWordWrap(true);
    m_hint->setText(tr("Other devices recorded with the window's device, each on its own clock: choose a source in "
                       "the Device panel and press Add to the session."));
    m_hint->setStyleSheet(QStringLiteral("color: palette(placeholder-text);"));
    m_layout->addWidget(m_hint);
    m_layout->addStretch();
}

OtherDevices::~OtherDevices()
{
    clear();
}

void OtherDevices::add(std::unique_ptr<devices::BlockSource> source, devices::session::LiveSessionOptions options,
                       const std::vector<std::string>& taken)
{
    std::vector<std::string> names = taken;
    for (const Device& d : m_devices) names.push_back(d.name);
    Device device;
    device.name = devices::session::partName(source->identity(), names);
    device.session = std::make_unique<devices::session::LiveSession>(std::move(source), std::move(options));
    device.box = new QWidget(this);
    device.box->setObjectName(QStringLiteral("otherDevice"));
    auto* title = new QLabel(QStringLiteral("<b>%1</b> — %2")
                                 .arg(QString::fromStdString(device.name).toHtmlEscaped(),
                                      QString::fromStdString(device.session->source().name()).toHtmlEscaped()),
                             device.box);
    title->setTextFormat(Qt::RichText);
    title->setWordWrap(true);
    device.link = new QLabel(device.box);
    device.link->setObjectName(QStringLiteral("otherDeviceLink"));
    auto* remove = new QPushButton(tr("Remove"), device.box);
    remove->setObjectName(QStringLiteral("removeDeviceButton"));
    remove->setToolTip(tr("Disconnect this device; the window's device stays."));
    device.plot = new LivePlotWidget(device.box);
    device.plot->setMinimumHeight(160);
    device.plot->setSource(device.session->buffer(), device.session->channels(),
                           device.session->source().nominalSampleRate_hz());
    auto* header = new QHBoxLayout;
    header->addWidget(title, 1);
    header->addWidget(remove);
    auto* layout = new QVBoxLayout(device.box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(header);
    layout->addWidget(device.link);
    layout->addWidget(device.plot, 1);
    m_layout->insertWidget(m_layout->count() - 1, device.box, 1);
    QWidget* box = device.box;
    connect(remove, &QPushButton::clicked, this, [this, box] {
        for (std::size_t i = 0; i < m_devices.size(); ++i)
            if (m_devices[i].box == box) emit removeRequested(i);
    });
    device.session->start();
    m_devices.push_back(std::move(device));
    m_hint->hide();
    update();
    emit changed();
}

void OtherDevices::remove(std::size_t index)
{
    if (index >= m_devices.size()) return;
    Device& device = m_devices[index];
    device.plot->clearSource();
    delete device.box;
    m_devices.erase(m_devices.begin() + static_cast<std::ptrdiff_t>(index));  // its session stops and goes
    m_hint->setVisible(m_devices.empty());
    emit changed();
}

void OtherDevices::clear()
{
    while (!m_devices.empty()) remove(m_devices.size() - 1);
}

void OtherDevices::setTimeBase(const std::optional<core::timing::ClockMapping>& windowClock, double origin_s,
                               const QString& label)
{
    for (Device& device : m_devices) {
        const auto own = device.session->source().hostClock();
        if (!windowClock || !own) {
            device.plot->setTimeOrigin(0.0, tr("Time since this device connected (s)"));
            continue;
        }
        // Where its time t shows: the window's device's time at the same
        // host instant, less the window's origin (the drifts move this by
        // microseconds over a screenful: one origin will do).
        const double t = own->reference_s;
        device.plot->setTimeOrigin(t - windowClock->device_s(own->host_s(t)) + origin_s, label);
    }
}

std::vector<std::string> OtherDevices::names() const
{
    std::vector<std::string> names;
    for (const Device& d : m_devices) names.push_back(d.name);
    return names;
}

std::optional<std::string> OtherDevices::startParts(const core::storage::SessionMetadata& request,
                                                    const devices::session::SessionOfDevices& session)
{
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        Device& device = m_devices[i];
        if (auto error = device.session->startRecordingPart(request, session.partFor(device.name))) {
            for (std::size_t j = 0; j < i; ++j) m_devices[j].session->stopRecording();
            return device.name + ": " + *error;
        }
    }
    return std::nullopt;
}

std::vector<std::string> OtherDevices::stopParts()
{
    std::vector<std::string> problems;
    for (Device& device : m_devices) {
        const auto summary = device.session->stopRecording();
        if (!summary) continue;
        if (!summary->stats.error.empty())
            problems.push_back(device.name + ": " + summary->stats.error);
        else if (!summary->stoppedBecause.empty())
            problems.push_back(device.name + ": " + summary->stoppedBecause);
    }
    return problems;
}

std::vector<std::string> OtherDevices::update()
{
    std::vector<std::string> problems;
    for (Device& device : m_devices) {
        if (const auto stopped = device.session->poll(); stopped && !stopped->stats.error.empty())
            problems.push_back(device.name + ": " + stopped->stats.error);
        const LinkCounters counters = linkCounters(device.session->stats(), device.session->source());
        device.link->setText(linkLine(counters));
        device.link->setStyleSheet(counters.healthy ? QString() : QStringLiteral("color: #b00020"));
    }
    return problems;
}

}  // namespace tactiscope::ui
