// ReferenceLink: a handshake on a worker thread, then an acquisition into a
// buffer of ten minutes.
#include "ui/modes/capacitive/ReferenceLink.h"

#include "devices/Acquisition.h"
#include "devices/DeviceDiscovery.h"
#include "ui/device/DeviceConnector.h"

#include <algorithm>

namespace tactiscope::ui {
namespace {

// A sweep and the unloaded stretches around it, at the reference's rate.
constexpr double kKept_s = 600.0;

}  // namespace

ReferenceLink::ReferenceLink(QObject* parent)
    : QObject(parent),
      m_connector(new DeviceConnector(
          {.disconnect = [this] { close(); },
           .connecting = [](const QString&) {},
           .connected = [this](std::unique_ptr<devices::BlockSource> source,
                               std::shared_ptr<devices::simulator::LoadRig>) { start(std::move(source)); },
           .failed =
               [this](const Problem& problem) {
                   emit failed(problem.detail.isEmpty() ? problem.what : problem.detail);
               }},
          this))
{
}

ReferenceLink::~ReferenceLink()
{
    close();
}

void ReferenceLink::open(const QString& path)
{
    const devices::DiscoveredDevice device{devices::DeviceBus::Serial, path.toStdString(), {}, path.toStdString()};
    m_connector->open(path, devices::deviceOpener(device, 921600, {}));
}

void ReferenceLink::close()
{
    if (m_acquisition) m_acquisition->stop();
    m_acquisition.reset();
    m_buffer.reset();
    m_channels.clear();
    m_name.clear();
}

std::optional<core::timing::ClockMapping> ReferenceLink::hostClock() const
{
    return m_acquisition ? m_acquisition->source().hostClock() : std::nullopt;
}

ReferenceDevice ReferenceLink::reference() const
{
    return {m_name, {}, m_channels, m_buffer, m_rate_hz, [this] { return hostClock(); }};
}

void ReferenceLink::start(std::unique_ptr<devices::BlockSource> source)
{
    m_channels = source->channels();
    m_rate_hz = source->nominalSampleRate_hz();
    // Its model and serial: what tells two boards apart, without the port.
    const devices::DeviceIdentity identity = source->identity();
    m_name = QString::fromStdString(identity.serial.empty() ? identity.model : identity.model + " " + identity.serial);
    const auto kept = static_cast<std::size_t>(std::max(1.0, m_rate_hz * kKept_s));
    m_buffer = std::make_shared<core::LiveBuffer>(std::max<std::size_t>(1, m_channels.size()), kept);
    m_acquisition = std::make_unique<devices::Acquisition>(std::move(source));
    m_acquisition->addSink(m_buffer);
    m_acquisition->start();
    emit opened();
}

}  // namespace tactiscope::ui
