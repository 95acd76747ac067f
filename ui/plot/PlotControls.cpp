// PlotControls: checkable actions fanned out to every plot.
#include "ui/plot/PlotControls.h"

#include "ui/plot/LivePlotWidget.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QToolBar>

namespace tactiscope::ui {

void addPlotControls(QMenu* view, QToolBar* display, const PlotControlTargets& targets)
{
    const auto toggle = [&](const QString& text, const QString& name, const QString& keys, const QString& tip,
                            void (LivePlotWidget::*set)(bool)) {
        QAction* action = view->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(keys));
        action->setToolTip(tip);
        QObject::connect(action, &QAction::toggled, view, [plots = targets.plots, set](bool on) {
            for (LivePlotWidget* plot : plots()) (plot->*set)(on);
        });
        display->addAction(action);
    };
    toggle(QObject::tr("&Pause display"), QStringLiteral("pauseAction"), QObject::tr("Ctrl+Space"),
           QObject::tr("Freeze the plots to look back; acquisition and recording go on (Ctrl+Space)"),
           &LivePlotWidget::setPaused);
    toggle(QObject::tr("&Hold value scale"), QStringLiteral("holdScaleAction"), QObject::tr("Ctrl+H"),
           QObject::tr("Stop autoscaling the value axes; drag them to adjust (Ctrl+H)"), &LivePlotWidget::setScaleHeld);
    QMenu* window = view->addMenu(QObject::tr("Time &window"));
    auto* windows = new QActionGroup(window);
    for (const double seconds : {5.0, 10.0, 30.0, 60.0}) {
        QAction* action = window->addAction(QObject::tr("%1 s").arg(seconds));
        action->setCheckable(true);
        action->setChecked(seconds == LivePlotWidget::kDefaultWindow_s);
        windows->addAction(action);
        QObject::connect(action, &QAction::triggered, view, [targets, seconds] {
            for (LivePlotWidget* plot : targets.plots()) plot->setWindowLength(seconds);
            if (targets.windowChanged) targets.windowChanged(seconds);
        });
    }
}

}  // namespace tactiscope::ui
