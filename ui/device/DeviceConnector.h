// Turns what the user asked to connect to (a simulator scenario, the probe
// emulator behind a pty, a port) into a streaming source, without ever
// blocking the window: a device's handshake runs on a worker thread of its
// own, and its result is dropped when a newer request or a disconnect came
// meanwhile. The window says what happens through the handlers.
#pragma once

#include "devices/BlockSource.h"
#include "devices/ReconnectingSource.h"
#include "ui/common/ProblemReport.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace tactiscope::devices::simulator {
class LoadRig;
}

namespace tactiscope::ui {

struct SourceRequest;

class DeviceConnector : public QObject {
    Q_OBJECT

public:
    struct Handlers {
        std::function<void()> disconnect;  // the current device goes before a new one
        std::function<void(const QString& label)> connecting;
        // The source, and the load rig when the simulator is a calibration rig.
        std::function<void(std::unique_ptr<devices::BlockSource>, std::shared_ptr<devices::simulator::LoadRig>)>
            connected;
        std::function<void(const Problem&)> failed;
    };

    DeviceConnector(Handlers handlers, QObject* parent);
    ~DeviceConnector() override;  // waits for the handshakes still running

    void request(const SourceRequest& request);
    void connectSimulator(const std::string& scenario);
    // Opens a device on a worker thread; it is reopened after an unplug.
    void open(const QString& label, devices::ReconnectingSource::Opener opener);
    // A handshake still running is dropped when it answers.
    void cancel();
    std::optional<QString> connecting() const { return m_connectingLabel; }

private:
    void finish(std::uint64_t attempt, std::unique_ptr<devices::BlockSource> source, const QString& error);

    Handlers m_handlers;
    std::optional<QString> m_connectingLabel;
    std::uint64_t m_attempt = 0;  // a newer attempt or a cancel drops older results
    // One per attempt, so a new attempt never waits for an old handshake;
    // declared last: joined before the members they report to go.
    std::vector<std::jthread> m_connectors;
};

}  // namespace tactiscope::ui
