// LiveStation: the devices into the pipeline, its poll, and its news as signals.
#include "ui/live/LiveStation.h"

#include "core/modes/ModeDefinition.h"
#include "devices/simulator/LoadRig.h"
#include "ui/common/VocabularyText.h"
#include "ui/device/ChannelRolesBox.h"
#include "ui/device/DeviceConnector.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/profiles/ActiveProfiles.h"

#include <algorithm>

namespace tactiscope::ui {
namespace {

std::optional<QString> refusalText(const std::optional<std::string>& refusal)
{
    if (!refusal) return std::nullopt;
    return QString::fromStdString(*refusal);
}

}  // namespace

LiveStation::LiveStation(QObject* parent)
    : QObject(parent),
      m_pipeline({})
{
    m_connector = new DeviceConnector(
        {.disconnect = [this] { disconnectDevices(); },
         .connecting = [this](const QString& label) { emit connecting(label); },
         .connected =
             [this](std::unique_ptr<devices::BlockSource> source, std::shared_ptr<devices::simulator::LoadRig> rig) {
                 connectSource(std::move(source), std::move(rig));
             },
         .failed = [this](const Problem& problem) { emit connectFailed(problem); }},
        this);
    m_adder = new DeviceConnector(
        {.disconnect = [] {},  // the window's device stays
         .connecting = [this](const QString& label) { emit told(tr("Connecting to %1…").arg(label)); },
         .connected = [this](std::unique_ptr<devices::BlockSource> source,
                             std::shared_ptr<devices::simulator::LoadRig>) { addSource(std::move(source)); },
         .failed = [this](const Problem& failure) { emit problem(failure); }},
        this);
    m_poll.setInterval(kPoll_ms);
    connect(&m_poll, &QTimer::timeout, this, &LiveStation::poll);
}

LiveStation::~LiveStation()
{
    m_connector->cancel();
    m_adder->cancel();
    m_pipeline.clear();  // ends a recording as complete; nobody is told any more
}

void LiveStation::request(const SourceRequest& request)
{
    m_connector->request(request);
}

void LiveStation::connectSimulator(const std::string& scenario)
{
    m_connector->connectSimulator(scenario);
}

void LiveStation::connectDevice(const QString& label, devices::ReconnectingSource::Opener opener)
{
    m_connector->open(label, std::move(opener));
}

bool LiveStation::isConnecting() const
{
    return m_connector->connecting().has_value();
}

devices::session::LiveSession* LiveStation::device()
{
    return m_pipeline.empty() ? nullptr : &m_pipeline.device(0);
}

const devices::session::LiveSession* LiveStation::device() const
{
    return m_pipeline.empty() ? nullptr : &m_pipeline.device(0);
}

// Each mode's active profile (a bad one told, the paper's used) and the
// roles remembered for this device, on the channels it still has.
devices::session::LiveSessionOptions LiveStation::sessionOptions(const devices::BlockSource& source)
{
    devices::session::LiveSessionOptions options;
    options.displaySeconds = LivePlotWidget::kMaxWindow_s + 2.0;
    for (const QString& mode : profileModes()) {
        ActiveProfile active = activeProfile(mode);
        if (!active.error.isEmpty()) emit problem(badProfile(mode, active.error));
        options.profiles.emplace(*core::modeFromString(mode.toStdString()), std::move(active.profile));
    }
    for (const auto& [channel, role] : rememberedRoles(source.identity()))
        if (std::ranges::find(source.channels(), channel, &core::ChannelDescriptor::name) != source.channels().end())
            options.roles.emplace(channel, role);
    return options;
}

void LiveStation::connectSource(std::unique_ptr<devices::BlockSource> source,
                                std::shared_ptr<devices::simulator::LoadRig> rig)
{
    disconnectDevices();
    if (!source) return;
    auto options = sessionOptions(*source);
    m_pipeline.add(std::move(source), std::move(options));
    m_loadRig = std::move(rig);
    auto& live = m_pipeline.device(0);
    // The source's own mode wins; a source that declares none runs in the
    // mode the window wants when its channels can feed it.
    if (!live.source().declaredMode() && m_wantedMode && !live.refusalOf(*m_wantedMode)) live.setMode(*m_wantedMode);
    m_pipeline.start();
    m_poll.start();
    emit connected();
}

void LiveStation::disconnectDevices()
{
    m_connector->cancel();  // a connect still in its handshake is dropped when it answers
    m_adder->cancel();
    if (m_pipeline.empty()) return;
    disarmTrigger();  // an open triggered session ends as complete
    stopRecording();  // the user ended the session by disconnecting
    m_poll.stop();
    emit disconnecting();
    m_pipeline.clear();
    m_loadRig.reset();
    m_wasArmed = false;
    emit armedChanged(false);
    emit devicesChanged();
    emit disconnected();
}

void LiveStation::addDevice(const SourceRequest& request)
{
    if (isRecording() || armed()) {
        emit told(tr("Stop recording first: a session keeps the devices it started with."));
        return;
    }
    m_adder->request(request);
}

void LiveStation::addSource(std::unique_ptr<devices::BlockSource> source)
{
    if (!isConnected()) return;  // the window's device went meanwhile
    const QString name = QString::fromStdString(source->name());
    auto options = sessionOptions(*source);
    if (const auto refusal = m_pipeline.add(std::move(source), std::move(options))) {
        emit problem({tr("Device not added"),
                      tr("%1 was not added to the session.").arg(name),
                      QString::fromStdString(*refusal),
                      {}});
        return;
    }
    m_pipeline.start();
    emit devicesChanged();
    emit told(tr("%1 added: Record records it with %2 into one session.")
                  .arg(name, QString::fromStdString(m_pipeline.name(0))));
}

std::optional<QString> LiveStation::removeDevice(std::size_t index)
{
    if (index == 0) return tr("The window's device is disconnected from the Device panel.");
    if (auto refusal = refusalText(m_pipeline.remove(index))) {
        emit told(*refusal);
        return refusal;
    }
    emit devicesChanged();
    return std::nullopt;
}

std::optional<QString> LiveStation::setMode(core::Mode mode)
{
    m_wantedMode = mode;
    if (!device()) return std::nullopt;
    return refusalText(device()->setMode(mode));
}

std::optional<QString> LiveStation::setRoles(const core::RoleAssignment& roles)
{
    if (!device()) return std::nullopt;
    if (auto refusal = refusalText(device()->setRoles(roles))) return refusal;
    rememberRoles(device()->source().identity(), roles);
    if (m_wantedMode && !device()->refusalOf(*m_wantedMode)) device()->setMode(*m_wantedMode);
    return std::nullopt;
}

std::optional<QString> LiveStation::tare()
{
    if (!device()) return tr("connect a probe to tare it");
    return refusalText(device()->tare());
}

void LiveStation::setStorePath(const QString& path)
{
    // Refused only while recording, which the window asks first.
    m_pipeline.setStorePath(path.toStdString());
}

QString LiveStation::storePath() const
{
    return QString::fromStdString(m_pipeline.storePath());
}

std::optional<QString> LiveStation::startRecording(const core::storage::SessionMetadata& metadata)
{
    if (!isConnected()) return tr("Connect a device to record.");
    if (auto refusal = refusalText(m_pipeline.startRecording(metadata))) return refusal;
    followRecording();
    return std::nullopt;
}

void LiveStation::stopRecording()
{
    if (auto end = m_pipeline.stopRecording()) emit recordingEnded(*end);
    followRecording();
}

std::optional<QString> LiveStation::armTrigger(const core::trigger::TriggerSettings& settings,
                                               const core::storage::SessionMetadata& metadata)
{
    if (armed()) disarmTrigger();
    if (auto refusal = refusalText(m_pipeline.armTrigger(settings, metadata))) return refusal;
    followRecording();
    return std::nullopt;
}

void LiveStation::disarmTrigger()
{
    if (auto end = m_pipeline.disarmTrigger()) emit recordingEnded(*end);
    followRecording();
}

void LiveStation::poll()
{
    const auto news = m_pipeline.poll();
    emit polled(news);
    for (const auto& end : news.ended) emit recordingEnded(end);
    followRecording();
}

// The record button and the locks follow the pipeline, whoever changed it.
void LiveStation::followRecording()
{
    if (isRecording() != m_wasRecording) {
        m_wasRecording = isRecording();
        emit recordingChanged(m_wasRecording);
    }
    if (armed() != m_wasArmed) {
        m_wasArmed = armed();
        emit armedChanged(m_wasArmed);
    }
}

}  // namespace tactiscope::ui
