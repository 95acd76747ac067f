// The session's other devices (issue 40): beside the window's device, each
// device added here streams through a LiveSession of its own, in the mode
// its channels declare (a load cell: general), and shows its channels in a
// live plot of its own under its name and link line. While any is here,
// Record records them all into one session of several devices
// (devices/session/SessionOfDevices): each device its own part, at its own
// rate and on its own clock, mapped onto the session's. The window's device
// stays the one the mode views read.
#pragma once

#include "core/storage/SessionSource.h"
#include "devices/BlockSource.h"
#include "devices/session/LiveSession.h"

#include <QWidget>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class QLabel;
class QVBoxLayout;

namespace tactiscope::devices::session {
class SessionOfDevices;
}

namespace tactiscope::ui {

class LivePlotWidget;

class OtherDevices : public QWidget {
    Q_OBJECT

public:
    explicit OtherDevices(QWidget* parent = nullptr);
    ~OtherDevices() override;

    // Streams `source` as another device, named unlike `taken` (the
    // window's device) and the others (devices::session::partName).
    void add(std::unique_ptr<devices::BlockSource> source, devices::session::LiveSessionOptions options,
             const std::vector<std::string>& taken);
    void remove(std::size_t index);
    void clear();
    bool empty() const { return m_devices.empty(); }
    std::vector<std::string> names() const;

    // Each device's recording as its part of `session`; on a refusal,
    // those started are stopped again and it says which device and why.
    std::optional<std::string> startParts(const core::storage::SessionMetadata& request,
                                          const devices::session::SessionOfDevices& session);
    // Ends them; what went wrong for any ("load-cell: the probe was lost").
    std::vector<std::string> stopParts();
    // On the window's status tick: each device's lists, clock and link
    // line; what stopped a device's part by itself (its disk), by name.
    std::vector<std::string> update();
    // Each plot's time axis on the window's device's: its stream time
    // `origin_s` shown as 0, titled `label`, each device's own time carried
    // over through the host's clock by the two mappings (`windowClock`,
    // the window's device's). A device whose clock is not known yet shows
    // its own time since connect, and says so.
    void setTimeBase(const std::optional<core::timing::ClockMapping>& windowClock, double origin_s,
                     const QString& label);
    const devices::session::LiveSession& session(std::size_t index) const { return *m_devices.at(index).session; }
    const LivePlotWidget& plot(std::size_t index) const { return *m_devices.at(index).plot; }

signals:
    void changed();  // a device added or removed
    void removeRequested(std::size_t index);

private:
    struct Device {
        std::string name;
        std::unique_ptr<devices::session::LiveSession> session;
        QWidget* box = nullptr;
        QLabel* link = nullptr;
        LivePlotWidget* plot = nullptr;
    };

    std::vector<Device> m_devices;
    QVBoxLayout* m_layout;
    QLabel* m_hint;
};

}  // namespace tactiscope::ui
