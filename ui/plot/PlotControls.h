// The display controls that act on every live plot together — pause, hold
// the value scale, the time window — so the traces and the mode's lanes stay
// aligned in time. They go into the View menu and a Display tool bar.
#pragma once

#include <functional>
#include <vector>

class QMenu;
class QToolBar;

namespace tactiscope::ui {

class LivePlotWidget;

struct PlotControlTargets {
    std::function<std::vector<LivePlotWidget*>()> plots;  // asked at each use: the views change
    std::function<void(double seconds)> windowChanged;    // e.g. the XY plot follows the time window
};

void addPlotControls(QMenu* view, QToolBar* display, const PlotControlTargets& targets);

}  // namespace tactiscope::ui
