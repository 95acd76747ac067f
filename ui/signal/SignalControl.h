// The main window's signal part (issue 57): Session ▸ Filters and math
// channels…, which sets the window's device's signal setup through the
// live station; View ▸ Traces as filtered, whether the traces show a
// filtered channel as filtered (the default: a filtered device is drawn
// once) or as it came; and under the traces a line that says what the
// filters are and how far each filtered trace lags its channel, over a
// plot of the math channels (and of the filtered ones, while the traces
// show the channels as they came). The plot is one of the traces' lanes
// (one clock, one scroll); line and plot are hidden while the device has
// no setup. The chain that computes them is the live pipeline's
// (core/signal/SignalChain through devices/session/LiveSession); this only
// asks and shows.
#pragma once

#include <QObject>
#include <QPointer>

class QAction;
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
    // View ▸ Traces as filtered.
    QAction* filteredTracesAction() const { return m_filteredTraces; }
    SignalDialog* showDialog(std::size_t device = 0);

signals:
    // The device's filters changed, or the traces are asked for filtered or
    // as they came: the traces bind again (LiveTraces::setFilteredTraces).
    void tracesChanged(bool filtered);

private:
    // The window's device's chain onto the plot, and the line above it.
    void bind();

    LiveStation& m_station;
    QWidget* m_window;
    QWidget* m_panel;
    QLabel* m_line;
    LivePlotWidget* m_plot;
    QPointer<SignalDialog> m_dialog;
    QAction* m_filteredTraces;
};

}  // namespace tactiscope::ui
