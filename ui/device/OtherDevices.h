// The session's other devices (issue 40): beside the window's device, each
// device the live station added after it (its pipeline's second, third, …)
// shows its channels in a live plot of its own under its name and link
// line, on the window's device's time axis. While any is here, Record
// records them all into one session of several devices (the pipeline's
// work): each device its own part, at its own rate and on its own clock,
// mapped onto the session's. The window's device stays the one the mode
// views read. The devices live in the station; this only shows them, and
// scrolls when there are more than fit.
#pragma once

#include <QScrollArea>

#include <cstddef>
#include <string>
#include <vector>

class QLabel;
class QVBoxLayout;

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class LivePlotWidget;
class LiveStation;

class OtherDevices : public QScrollArea {
    Q_OBJECT

public:
    explicit OtherDevices(QWidget* parent = nullptr);

    // Shows `station`'s other devices as they are added and removed, their
    // links and time axes each poll; Remove asks the station.
    void watch(LiveStation& station);

    bool empty() const { return m_devices.empty(); }
    std::size_t size() const { return m_devices.size(); }
    std::vector<std::string> names() const;
    const devices::session::LiveSession& session(std::size_t index) const;
    const LivePlotWidget& plot(std::size_t index) const { return *m_devices.at(index).plot; }

signals:
    void changed();  // a device added or removed

private:
    struct Device {
        const devices::session::LiveSession* session = nullptr;
        std::string name;
        QWidget* box = nullptr;
        QLabel* link = nullptr;
        LivePlotWidget* plot = nullptr;
    };
    void follow();  // the station's devices now
    void add(const devices::session::LiveSession& session, const std::string& name);
    void update();
    // Each plot's time axis on the window's device's: its recording origin
    // (or connect) shown as 0, each device's own time carried over through
    // the host's clock by the two mappings. A device whose clock is not
    // known yet shows its own time since connect, and says so.
    void setTimeBase();

    LiveStation* m_station = nullptr;
    std::vector<Device> m_devices;
    QVBoxLayout* m_layout;
    QLabel* m_hint;
};

}  // namespace tactiscope::ui
