// The main window's plots of the window's device as one: its traces (as
// its filters give them, unless asked for as they came) and
// every mode view's lanes under them, on one clock (the recording's while
// recording, as the markers, dialogs and the stored session read it, else
// since connect), scrolled together while paused under one banner, each
// marker on all of them. It watches the live station for the device's
// channels and clock.
#pragma once

#include <QObject>
#include <QString>

#include <vector>

namespace tactiscope::ui {

class LivePlotWidget;
class LiveStation;

class LiveTraces : public QObject {
    Q_OBJECT

public:
    // `traces` above `lanes`; all outlive this.
    LiveTraces(LiveStation& station, LivePlotWidget* traces, std::vector<LivePlotWidget*> lanes, QObject* parent);

    std::vector<LivePlotWidget*> plots() const;
    // The device's channels again (other roles, other filters).
    void showChannels();
    // Whether the traces show a filtered channel as filtered (its signal
    // chain's display) or as it came; the raw channels either way when
    // none is filtered.
    void setFilteredTraces(bool filtered);
    bool filteredTraces() const { return m_filteredTraces; }
    // A marker at a time of the window's device's recording.
    void addMarker(double time_s, const QString& note);

private:
    void updateTimeBase();

    LiveStation& m_station;
    LivePlotWidget* m_traces;
    std::vector<LivePlotWidget*> m_lanes;
    bool m_filteredTraces = true;
    bool m_showingFiltered = false;  // bound to a chain's display, whose channels do not grow
};

}  // namespace tactiscope::ui
