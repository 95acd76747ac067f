// OtherDevices: a title, a link line and a live plot per device the
// station added beside the window's.
#include "ui/device/OtherDevices.h"

#include "devices/session/LiveSession.h"
#include "ui/device/LinkStatus.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {

OtherDevices::OtherDevices(QWidget* parent)
    : QScrollArea(parent),
      m_layout(nullptr),
      m_hint(new QLabel)
{
    setObjectName(QStringLiteral("otherDevices"));
    // A device's name on one line and a trace beside its axis; more devices
    // than fit scroll, so the window keeps its width on a laptop.
    setMinimumWidth(300);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    auto* content = new QWidget;
    m_layout = new QVBoxLayout(content);
    m_hint->setWordWrap(true);
    m_hint->setText(tr("Other devices recorded with the window's device, each on its own clock: choose a source in "
                       "the Device panel and press Add to the session."));
    m_hint->setStyleSheet(QStringLiteral("color: palette(placeholder-text);"));
    m_layout->addWidget(m_hint);
    m_layout->addStretch();
    setWidget(content);
}

void OtherDevices::watch(LiveStation& station)
{
    m_station = &station;
    connect(&station, &LiveStation::devicesChanged, this, &OtherDevices::follow);
    connect(&station, &LiveStation::disconnecting, this, [this] {
        // The devices go with the window's: nothing may read them any more.
        while (!m_devices.empty()) {
            m_devices.back().plot->clearSource();
            delete m_devices.back().box;
            m_devices.pop_back();
        }
    });
    connect(&station, &LiveStation::polled, this, &OtherDevices::update);
}

std::vector<std::string> OtherDevices::names() const
{
    std::vector<std::string> names;
    for (const Device& d : m_devices) names.push_back(d.name);
    return names;
}

const devices::session::LiveSession& OtherDevices::session(std::size_t index) const
{
    return *m_devices.at(index).session;
}

// Boxes for the devices added since, none for those gone.
void OtherDevices::follow()
{
    const auto& pipeline = m_station->pipeline();
    std::vector<const devices::session::LiveSession*> now;
    for (std::size_t i = 1; i < pipeline.size(); ++i) now.push_back(&pipeline.device(i));
    for (auto it = m_devices.begin(); it != m_devices.end();) {
        if (std::ranges::find(now, it->session) != now.end()) {
            ++it;
            continue;
        }
        it->plot->clearSource();
        delete it->box;
        it = m_devices.erase(it);
    }
    for (std::size_t i = 1; i < pipeline.size(); ++i)
        if (std::ranges::none_of(m_devices, [&](const Device& d) { return d.session == &pipeline.device(i); }))
            add(pipeline.device(i), pipeline.name(i));
    m_hint->setVisible(m_devices.empty());
    update();
    emit changed();
}

void OtherDevices::add(const devices::session::LiveSession& session, const std::string& name)
{
    Device device;
    device.session = &session;
    device.name = name;
    device.box = new QWidget(widget());
    device.box->setObjectName(QStringLiteral("otherDevice"));
    auto* title = new QLabel(QStringLiteral("<b>%1</b> — %2")
                                 .arg(QString::fromStdString(name).toHtmlEscaped(),
                                      QString::fromStdString(session.source().name()).toHtmlEscaped()),
                             device.box);
    title->setTextFormat(Qt::RichText);
    title->setWordWrap(true);
    device.link = new QLabel(device.box);
    device.link->setObjectName(QStringLiteral("otherDeviceLink"));
    device.link->setWordWrap(true);
    auto* remove = new QPushButton(tr("Remove"), device.box);
    remove->setObjectName(QStringLiteral("removeDeviceButton"));
    remove->setToolTip(tr("Disconnect this device; the window's device stays."));
    device.plot = new LivePlotWidget(device.box);
    device.plot->setMinimumHeight(160);
    device.plot->setSource(session.buffer(), session.channels(), session.source().nominalSampleRate_hz());
    auto* header = new QHBoxLayout;
    header->addWidget(title, 1);
    header->addWidget(remove);
    auto* layout = new QVBoxLayout(device.box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(header);
    layout->addWidget(device.link);
    layout->addWidget(device.plot, 1);
    m_layout->insertWidget(m_layout->count() - 1, device.box, 1);
    connect(remove, &QPushButton::clicked, this, [this, live = &session] {
        const auto& pipeline = m_station->pipeline();
        for (std::size_t i = 1; i < pipeline.size(); ++i)
            if (&pipeline.device(i) == live) m_station->removeDevice(i);
    });
    m_devices.push_back(std::move(device));
}

void OtherDevices::update()
{
    for (Device& device : m_devices) {
        const LinkCounters counters = linkCounters(device.session->stats(), device.session->source());
        device.link->setText(linkLine(counters));
        device.link->setStyleSheet(counters.healthy ? QString() : QStringLiteral("color: #b00020"));
        device.plot->showMoreChannels(device.session->channels());  // a board's new layout
    }
    setTimeBase();
}

void OtherDevices::setTimeBase()
{
    const auto* window = m_station ? m_station->device() : nullptr;
    if (!window) return;
    const auto windowClock = window->source().hostClock();
    const auto origin = window->recordingOrigin_s();
    const QString label = origin ? tr("Recording time (s)") : tr("Time since connect (s)");
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
        device.plot->setTimeOrigin(t - windowClock->device_s(own->host_s(t)) + origin.value_or(0.0), label);
    }
}

}  // namespace tactiscope::ui
