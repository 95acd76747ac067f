// The session bar's mode against the window's device (the station): a mode
// chosen runs when the device's channels feed it, else the bar goes back
// to the device's mode and the operator is told which channels it needs;
// a device connected shows its own mode in the bar; roles chosen in the
// device panel rebuild the processors and run the bar's mode when they now
// can. The mode's view under the traces and its XY plot follow. The main
// window names no mode: this asks the station and the modes' entries.
#pragma once

#include "core/Vocabulary.h"
#include "core/modes/ChannelRoles.h"

#include <QObject>
#include <QString>

#include <functional>

class QDockWidget;
class QWidget;

namespace tactiscope::ui {

class DevicePanel;
class LiveStation;
class LiveTraces;
class ModeViews;
class SessionBar;
class XYPlotWidget;

class ModeChoice : public QObject {
    Q_OBJECT

public:
    struct Widgets {
        SessionBar* bar = nullptr;
        ModeViews* views = nullptr;
        LiveTraces* traces = nullptr;
        DevicePanel* panel = nullptr;
        XYPlotWidget* xy = nullptr;
        QDockWidget* xyDock = nullptr;
    };
    ModeChoice(LiveStation& station, Widgets widgets, std::function<void(const QString&)> tell, QWidget* window);

    // The bar's mode; false (and the refusal shown) when the device cannot feed it.
    bool setMode(core::Mode mode);
    // The views of a mode bound again (its probe or calibration changed), then shown.
    void showMode(core::Mode mode);
    // The bar's mode's view, when the device runs it; its XY plot.
    void showView();

private:
    void chosen();
    void connected();
    void setRoles(const core::RoleAssignment& roles);

    LiveStation& m_station;
    Widgets m_widgets;
    std::function<void(const QString&)> m_tell;
    QWidget* m_window;
};

}  // namespace tactiscope::ui
