// The main window's signal part (issue 57): Session ▸ Filters and math
// channels…, which sets the window's device's signal setup through the
// live station, and the plot of what that setup gives, live: each filtered
// channel and each math channel, under a line that says what they are and
// how far each filtered trace lags its channel. The plot is one of the
// traces' lanes (one clock, one scroll), hidden while the device has no
// setup. The chain that computes them is the live pipeline's
// (core/signal/SignalChain through devices/session/LiveSession); this only
// asks and shows.
#pragma once

#include <QObject>
#include <QPointer>

class QLabel;
class QMenu;
class QWidget;

namespace tactiscope::ui {

class LivePlotWidget;
class LiveStation;
class SignalDialog;

class SignalControl : public QObject {
    Q_OBJECT

public:
    SignalControl(LiveStation& station, QWidget* window);

    // The line and the plot, for the window's layout; hidden without a setup.
    QWidget* panel() const { return m_panel; }
    LivePlotWidget* plot() const { return m_plot; }
    void addActions(QMenu* session);
    SignalDialog* showDialog();

private:
    // The window's device's chain onto the plot, and the line above it.
    void bind();

    LiveStation& m_station;
    QWidget* m_window;
    QWidget* m_panel;
    QLabel* m_line;
    LivePlotWidget* m_plot;
    QPointer<SignalDialog> m_dialog;
};

}  // namespace tactiscope::ui
