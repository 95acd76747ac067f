// View ▸ Signal health, live (issue 57): each channel of the window's
// device, and its filtered and math channels, judged as a report's
// "Signal quality" judges a recording (core/dsp/SignalHealth: mains hum in
// the channel's unit, noise floor, drift per hour with its ±, clipped
// samples; a capacitive beam's creep after its load steps), over what came
// since the panel opened, the recording began or the user pressed Restart.
// Samples are read at each poll while the dock is shown and the table is
// redrawn once a second; samples the device lost are counted as missing,
// never bridged. The creep's fit takes longer the longer the record: it
// runs off the GUI thread, again after every 10 s of new samples.
#pragma once

#include "core/LiveBuffer.h"
#include "core/dsp/SignalHealth.h"
#include "core/report/SignalQuality.h"
#include "core/signal/SignalChain.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>
#include <span>
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
    void keep(std::size_t row, std::span<const double> values);
    void redraw();
    void fitCreep();  // on a worker thread, when due

    LiveStation& m_station;
    QDockWidget* m_dock;
    QLabel* m_line;
    QTableWidget* m_table;
    QLabel* m_creepLine;  // a beam's creep, under the table
    std::weak_ptr<const core::signal::SignalChain> m_chainSeen;
    std::vector<Source> m_sources;
    std::vector<core::dsp::HealthAccumulator> m_accumulators;  // a row each
    std::vector<core::report::ChannelQuality> m_channels;
    double m_rate_hz = 0.0;
    QString m_since;
    std::uint64_t m_samples = 0;  // of the device's, since the restart
    QElapsedTimer m_sinceRedraw;
    // A beam's samples since the restart, for its creep: a row each, empty
    // but for a beam's (up to core::report::kMostCreepSamples).
    std::vector<std::vector<double>> m_beamSamples;
    std::uint64_t m_creepFittedAt = 0;  // m_samples when the last fit began
    bool m_creepFitting = false;
    std::uint64_t m_generation = 0;  // a restart's: an older fit's result is dropped
};

}  // namespace tactiscope::ui
