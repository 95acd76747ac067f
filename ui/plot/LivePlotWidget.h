// LivePlotWidget shows the newest seconds of every channel of one device as
// scrolling traces. It pulls new samples from a LiveBuffer on a frame timer
// (about 40 Hz, re-armed only after a frame is built so frames never pile up),
// keeps its own history of the last kHistory_s, reduces the visible part to
// min/max per pixel column and replots only when something changed.
// Channels with the same display unit share a lane; each unit gets its own
// lane, stacked vertically.
//
// Samples the device lost are drawn as a gap — the line broken and a grey
// band over the missing time — never joined across.
//
// Time base: the plot keeps the stream's seconds (since connect) inside,
// and shows them from an origin — the recording's start while recording,
// so the axis, the markers and the dialogs read the same clock — with the
// axis saying which. Operators' markers are drawn where they were put.
//
// Paused, the view stops scrolling while samples keep arriving into the
// history; the user drags (and wheel-zooms) the time axis back through it.
// With the scale held, the value axes stop autoscaling and can be dragged.
//
// GUI thread only. QCustomPlot stays out of this header on purpose: its
// header is expensive to compile.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/RingBuffer.h"
#include "core/signal/MinMaxDecimation.h"
#include "core/signal/ScrollingMinMax.h"
#include "ui/common/DisplayUnits.h"
#include "ui/plot/AxisAutoRange.h"

#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QCustomPlot;
class QCPGraph;
class QCPItemRect;
class QCPAbstractItem;
class QCPAxisRect;
class QCPMarginGroup;
class QCPRange;

namespace tactiscope::ui {

class LivePlotWidget : public QWidget {
    Q_OBJECT

public:
    static constexpr double kDefaultWindow_s = 10.0;
    static constexpr double kMaxWindow_s = 60.0;
    static constexpr double kHistory_s = 180.0;  // how far back a paused view can scroll

    explicit LivePlotWidget(QWidget* parent = nullptr);
    ~LivePlotWidget() override;

    // Starts plotting `buffer`, whose channels are described by `channels`,
    // replacing whatever was shown. sampleRate_hz sizes the local history.
    // `units` (one per channel) replaces the display units of the channels'
    // kinds, e.g. for derived signals such as the detector's output.
    void setSource(std::shared_ptr<const core::LiveBuffer> buffer, const std::vector<core::ChannelDescriptor>& channels,
                   double sampleRate_hz, std::vector<DisplayUnit> units = {});
    // The channels of the same buffer, more of them (a board began to
    // print another value): their traces are added, the history kept.
    void showMoreChannels(const std::vector<core::ChannelDescriptor>& channels);
    // Stops plotting and clears the traces.
    void clearSource();

    // Length of the scrolling time window, clamped to (0, kMaxWindow_s].
    void setWindowLength(double seconds);
    // Until a full window has arrived, the traces grow from this stream
    // time rather than from their first sample: a lane that began later
    // than the plots it lines up with (filters set mid-stream, from 0)
    // keeps their time axis. None: from its first sample.
    void setGrowsFrom(std::optional<double> time_s) { m_growsFrom_s = time_s; }
    double windowLength_s() const { return m_window_s; }

    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Holds every lane's value range (no autoscaling) while set.
    void setScaleHeld(bool held);
    bool isScaleHeld() const { return m_scaleHeld; }
    // The time range shown, in the stream's seconds.
    std::pair<double, double> visibleTimeRange() const;
    // A lane's value-axis range, in display units.
    std::pair<double, double> valueRange(std::size_t lane) const;
    // Shows another time range (paused only), as a drag would.
    void scrollTo(double start_s);
    // Shows [start_s, end_s] (paused only) because another plot moved there:
    // no userScrolled back.
    void followTimeRange(double start_s, double end_s);
    // The time axis shows stream time − origin_s, titled `label`.
    void setTimeOrigin(double origin_s, const QString& label);
    double timeOrigin_s() const { return m_origin_s; }
    QString timeAxisLabel() const;
    // An operator's marker at a stream time, drawn across every lane; the
    // note labels it in the top lane.
    void addMarker(double t_s, const QString& note);
    std::size_t markerCount() const;
    // A detector's event (a defect) at a stream time, drawn as a solid line
    // across every lane with its text; clearEvents() starts a new panel.
    void addEvent(double t_s, const QString& text);
    void clearEvents();
    std::size_t eventCount() const;
    // A value a lane is read against (the detector's threshold on R), drawn
    // as a dashed line and kept in view; none removes it. SI units.
    void setThreshold(std::size_t lane, std::optional<double> value_si);
    std::optional<double> threshold(std::size_t lane) const;
    // Narrow lanes under a plot that names the clock title their time axis
    // "t (s)" only.
    void setCompactTimeTitle(bool compact);
    // Whether this plot shows the paused banner (one banner for the window).
    void setPausedBannerShown(bool shown);

    // Number of stacked lanes (one per distinct display unit).
    std::size_t laneCount() const { return m_lanes.size(); }
    // Points drawn for a channel in the last frame (after decimation).
    int drawnPointCount(std::size_t channel) const;
    // Samples per channel taken from the buffer since setSource().
    std::uint64_t samplesReceived() const { return m_cursor.next; }
    // Frames drawn since construction (a frame is drawn only when something changed).
    std::uint64_t framesDrawn() const { return m_framesDrawn; }
    // Samples the display missed because it fell behind the buffer.
    std::uint64_t samplesOverrun() const { return m_cursor.overrun; }
    // The gaps drawn in the last frame (stream seconds).
    const std::vector<core::signal::TimeGap>& gapsShown() const { return m_gaps; }

signals:
    // Paused: the user moved the time axis (a drag, a wheel, scrollTo), so
    // the window's other plots can follow.
    void userScrolled(double start_s, double end_s);

private slots:
    // One frame: takes new samples and redraws if anything changed. Run by
    // the frame timer (and invoked by name from the display benchmark).
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;  // a cut marker note's whole text as a tooltip

private:
    struct Lane {
        QCPAxisRect* rect = nullptr;
        AxisRange range{0.0, 0.0};  // empty until the first frame
        double scale = 1.0;         // SI → display
        std::optional<double> threshold_si;
        QCPAbstractItem* thresholdLine = nullptr;
        std::optional<AxisRange> levels;  // a lane of named levels keeps them all in view
    };

    void scheduleFrame();
    void buildPlotItems(const std::vector<core::ChannelDescriptor>& channels, const std::vector<DisplayUnit>& units);
    void removePlotItems();
    void moveLegendTo(QCPAxisRect* rect);
    double legendHeadroom(const QCPAxisRect* rect) const;
    void updateInteractions();
    void followLive(double start_s, bool arrived);
    void decimatedPoints(std::size_t channel, double start_s, double end_s);
    void draw(double start_s, double end_s);
    void drawGapBands();
    void drawMarkers();
    void applyTimeAxis(QCPAxisRect* rect);
    void syncTimeAxes(const QCPRange& range);
    std::uint64_t firstIndexAtOrAfter(double t_s) const;

    QCustomPlot* m_plot = nullptr;
    QCPMarginGroup* m_laneMargins = nullptr;  // keeps lanes' axes aligned
    QTimer m_frameTimer;
    double m_window_s = kDefaultWindow_s;
    std::optional<double> m_growsFrom_s;
    bool m_paused = false;
    bool m_scaleHeld = false;
    bool m_viewChanged = false;  // paused: the user moved the view since the last frame
    bool m_drawing = false;      // draw() is setting the axes itself
    std::uint64_t m_framesDrawn = 0;
    QWidget* m_pausedBanner = nullptr;

    std::shared_ptr<const core::LiveBuffer> m_buffer;
    core::LiveCursor m_cursor;
    core::LiveChunk m_chunk;

    // The display's own history, so each frame reads only new samples.
    std::unique_ptr<core::RingBuffer<double>> m_time;
    std::vector<core::RingBuffer<double>> m_values;
    // Live: the decimated window per channel, extended frame by frame.
    std::vector<core::signal::ScrollingMinMax> m_scrolling;

    std::vector<Lane> m_lanes;
    std::vector<QCPGraph*> m_graphs;       // one per channel
    std::vector<std::size_t> m_graphLane;  // lane index per channel
    std::vector<double> m_graphScale;      // SI → display factor per channel
    double m_sampleRate_hz = 0.0;
    std::vector<core::signal::TimeGap> m_gaps;
    std::vector<QCPItemRect*> m_gapBands;  // one per gap and lane, reused frame to frame
    double m_origin_s = 0.0;
    QString m_timeLabel;
    struct Marker {
        double t_s = 0.0;
        QString note;
        bool event = false;  // the detector's, not the operator's
    };
    std::vector<Marker> m_markers;
    std::vector<QCPAbstractItem*> m_markerItems;  // redrawn when lanes or markers change
    bool m_showsBanner = true;
    bool m_compactTimeTitle = false;
    bool m_following = false;  // followTimeRange() is moving the axes

    // Per-frame scratch, kept to avoid reallocating every frame.
    std::vector<double> m_visibleTime;
    std::vector<double> m_visibleValues;
    std::vector<double> m_decimatedTime;
    std::vector<double> m_decimatedValues;
};

}  // namespace tactiscope::ui
