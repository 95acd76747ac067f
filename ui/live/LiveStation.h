// The GUI's live workflow (issue 52), as pv::Session is PulseView's: one
// QObject owns the live pipeline (devices/session/LivePipeline: the
// window's device first, the session's other devices after it), the
// connectors that open devices off the GUI thread, and the poll. Every
// recording the window makes, by hand, with several devices or by the
// trigger, goes through that one pipeline, the one the CLI's `record`
// runs. It never opens a dialog or touches a widget: the live widgets
// connect to its signals themselves and read the pipeline; the main window
// reacts where a dialog is needed (the verdict, a problem box).
//
// Threading: the GUI thread; devices are opened on worker threads by the
// connectors, and arrive here queued.
#pragma once

#include "core/Vocabulary.h"
#include "core/modes/ChannelRoles.h"
#include "core/storage/SessionSource.h"
#include "devices/BlockSource.h"
#include "devices/ReconnectingSource.h"
#include "devices/session/LivePipeline.h"
#include "ui/common/ProblemReport.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <string>

namespace tactiscope::devices::simulator {
class LoadRig;
}

namespace tactiscope::ui {

class DeviceConnector;
struct SourceRequest;

class LiveStation : public QObject {
    Q_OBJECT

public:
    // How often the pipeline is polled and the live widgets updated.
    static constexpr int kPoll_ms = 250;

    explicit LiveStation(QObject* parent = nullptr);
    ~LiveStation() override;  // ends a recording, with everything kept

    // The window's device: replaces every device connected (a recording
    // ends first, as a stop would end it). A request is opened on a worker
    // thread; a source given is connected at once.
    void request(const SourceRequest& request);
    void connectSimulator(const std::string& scenario);
    void connectDevice(const QString& label, devices::ReconnectingSource::Opener opener);
    void connectSource(std::unique_ptr<devices::BlockSource> source,
                       std::shared_ptr<devices::simulator::LoadRig> rig = {});
    void disconnectDevices();
    bool isConnected() const { return !m_pipeline.empty(); }
    bool isConnecting() const;
    // The window's device; null when none is connected.
    devices::session::LiveSession* device();
    const devices::session::LiveSession* device() const;
    // Every device of the session, the window's first.
    devices::session::LivePipeline& pipeline() { return m_pipeline; }
    const devices::session::LivePipeline& pipeline() const { return m_pipeline; }
    // The simulator's load rig when it is a calibration rig.
    const std::shared_ptr<devices::simulator::LoadRig>& loadRig() const { return m_loadRig; }

    // Another device beside the window's, recorded with it into one session
    // of several (its part); refused while recording or armed.
    void addDevice(const SourceRequest& request);
    void addSource(std::unique_ptr<devices::BlockSource> source);
    std::optional<QString> removeDevice(std::size_t index);

    // The mode the window wants: the device runs in it when its channels
    // feed it (a device that declares its own starts in that one); the
    // refusal otherwise.
    std::optional<QString> setMode(core::Mode mode);
    std::optional<QString> setRoles(const core::RoleAssignment& roles);
    // The mode's zero on the window's device; why not, when its rule refuses.
    std::optional<QString> tare();
    // The store recordings go to and calibrations are read from.
    void setStorePath(const QString& path);
    QString storePath() const;

    // Records every device (a session of one, or of several); the reason
    // when it cannot start.
    std::optional<QString> startRecording(const core::storage::SessionMetadata& metadata);
    void stopRecording();  // recordingEnded() tells the session's end
    bool isRecording() const { return m_pipeline.isRecording(); }
    std::optional<QString> armTrigger(const core::trigger::TriggerSettings& settings,
                                      const core::storage::SessionMetadata& metadata);
    void disarmTrigger();  // an open triggered session ends as complete
    bool armed() const { return m_pipeline.triggerArmed(); }

signals:
    void connecting(const QString& label);
    void connectFailed(const Problem& problem);
    void connected();      // the window's device streams: bind to device()
    void disconnecting();  // the window's device is about to go: let go of it
    void disconnected();
    void devicesChanged();  // another device added or removed
    // Each poll's news, after the pipeline took it: the widgets update.
    void polled(const devices::session::PipelineNews& news);
    void recordingChanged(bool recording);  // started or ended, by hand or by the trigger
    void recordingEnded(const devices::session::RecordingEnd& end);
    void armedChanged(bool armed);
    // Something the user must hear (a bad profile, a device that cannot be
    // added): for the window to show.
    void problem(const Problem& problem);
    void told(const QString& line);  // a line for the status bar

private:
    devices::session::LiveSessionOptions sessionOptions(const devices::BlockSource& source);
    void poll();
    void followRecording();

    devices::session::LivePipeline m_pipeline;
    std::shared_ptr<devices::simulator::LoadRig> m_loadRig;
    std::optional<core::Mode> m_wantedMode;  // none until the window says
    QTimer m_poll;
    bool m_wasRecording = false;
    bool m_wasArmed = false;
    DeviceConnector* m_connector = nullptr;  // the window's device
    DeviceConnector* m_adder = nullptr;      // the other devices
};

}  // namespace tactiscope::ui
