// View ▸ Signal health, live (issue 57): each channel of the window's
// device, and its filtered and math channels, judged as a report's
// "Signal quality" judges a recording (core/dsp/SignalHealth: mains hum in
// the channel's unit, noise floor, drift per hour with its ±, clipped
// samples), over what came since the panel opened, the recording began or
// the user pressed Restart. Samples are read at each poll while the dock
// is shown and the table is redrawn once a second; samples the device lost
// are counted as missing, never bridged.
#pragma once

#include "core/LiveBuffer.h"
#include "core/dsp/SignalHealth.h"
#include "core/report/SignalQuality.h"
#include "core/signal/SignalChain.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>
#include <vector>

class QDockWidget;
class QLabel;
class QMainWindow;
class QTableWidget;

namespace tactiscope::ui {

class LiveStation;

class LiveHealth : public QObject {
    Q_OBJECT

public:
    LiveHealth(LiveStation& station, QMainWindow* window);
    QDockWidget* dock() const { return m_dock; }
    QTableWidget* table() const { return m_table; }
    // What the figures are over ("Over 12 s since the recording began.").
    QLabel* line() const { return m_line; }
    // The figures as the table shows them, a channel each.
    const std::vector<core::report::ChannelQuality>& channels() const { return m_channels; }

private:
    // One of the buffers read: the device's own, or its chain's outputs.
    struct Source {
        std::shared_ptr<const core::LiveBuffer> buffer;
        std::vector<int> rows;  // per column of it: its row, or −1 (a probe's decisions)
        core::LiveCursor cursor;
        core::LiveChunk chunk;
        double lastTime_s = 0.0;
        bool started = false;
    };

    void restart(const QString& since);
    void update();  // new samples in; the table once a second
    void read(Source& source);
    void redraw();

    LiveStation& m_station;
    QDockWidget* m_dock;
    QLabel* m_line;
    QTableWidget* m_table;
    std::weak_ptr<const core::signal::SignalChain> m_chainSeen;
    std::vector<Source> m_sources;
    std::vector<core::dsp::HealthAccumulator> m_accumulators;  // a row each
    std::vector<core::report::ChannelQuality> m_channels;
    double m_rate_hz = 0.0;
    QString m_since;
    std::uint64_t m_samples = 0;  // of the device's, since the restart
    QElapsedTimer m_sinceRedraw;
};

}  // namespace tactiscope::ui
