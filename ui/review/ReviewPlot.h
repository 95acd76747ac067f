// The review view's plot of one stored session: a lane per quantity on a
// shared time axis — the mode's physical quantities, or the stored channels
// as they are (core/derived/SessionLanes.h) — read from the store window by
// window
// (core::storage::readTraceWindow) each time the view moves, so the whole
// session shows from the overview pyramid and a zoom reads only the samples
// on screen; nothing of the session is kept beyond what is drawn.
//
// Under the lanes, a marker lane with one row per source (recorded events,
// a re-analysis, readings, notes). The mouse drags and wheels the time axis
// only; the values autoscale to what is shown. Hovering shows a readout of
// every channel at the pointer; a click pins the cursor (where a note goes).
// Lost stretches are greyed.
#pragma once

#include "core/derived/SessionLanes.h"
#include "core/storage/SessionStore.h"
#include "core/storage/TraceWindow.h"
#include "ui/common/DisplayUnits.h"

#include <QColor>
#include <QPointF>
#include <QStringList>
#include <QTimer>
#include <QWidget>

#include <optional>
#include <vector>

class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QLabel;
class QMouseEvent;

namespace tactiscope::ui {

struct MarkerSpan {
    double start_s = 0.0;
    double end_s = 0.0;  // equal to start for an instant
    int row = 0;
    QColor colour;
};

class ReviewPlot : public QWidget {
    Q_OBJECT

public:
    // The store must outlive the plot. `options`: the stored channels as
    // they are instead of the mode's physical quantities, or another
    // calibration to compute them through.
    ReviewPlot(core::storage::SessionSource& store, const core::storage::SessionSummary& session,
               const core::derived::LaneOptions& options, QWidget* parent);
    // What the derived lanes were computed with, or why there are none
    // (empty for a mode without them).
    const std::string& derivedBasis() const { return m_lanes.basis; }
    const std::string& derivedProblem() const { return m_lanes.problem; }
    bool showsDerived() const { return m_lanes.derived; }
    std::vector<std::string> laneNames() const;

    void setMarkers(const QStringList& rows, const std::vector<MarkerSpan>& spans);

    // The time span shown, clipped to the session and to at least a few samples.
    void setRange(double from_s, double to_s);
    double from_s() const;
    double to_s() const;
    void showWholeSession();
    void zoom(double factor);  // < 1 zooms in, about the middle
    // Centres the view on t without zooming out past `width_s`.
    void centreOn(double time_s, double width_s);

    // The pinned cursor (a click, or set here): where a note is added.
    void setCursorTime(double time_s);
    std::optional<double> cursorTime() const { return m_cursor_s; }
    // The replay position, drawn as a line; none hides it.
    void setPlayhead(std::optional<double> time_s);
    // "t = … s │ name: value unit │ …" at a time, from what is shown.
    QString readoutAt(double time_s) const;

    // What each lane shows now (for tests and the readout).
    const core::storage::TraceWindow& shown(std::size_t channel) const { return m_windows.at(channel); }
    // Reads the shown span again now instead of at the next event-loop turn;
    // a store that can no longer be read leaves the lanes as they were and
    // says so through readFailed; the next read that works says samplesRead.
    void reload();
    void saveImage(const QString& path) const;  // PNG or SVG by suffix

signals:
    void rangeChanged(double from_s, double to_s);
    void cursorPinned(double time_s);
    void readFailed(const QString& error);
    void samplesRead();

private:
    void syncRange(QCPAxisRect* source);
    void showHover(QMouseEvent* event);
    void pinCursor(QMouseEvent* event);
    void placeLines(std::vector<QCPItemStraightLine*>& lines, std::optional<double> time_s);
    std::vector<QCPItemStraightLine*> makeLines(const QPen& pen);
    DisplayUnit unitOf(std::size_t lane) const;
    int laneLine() const;  // a tick label's height
    void fitTickCounts();

    core::storage::SessionSource& m_store;
    core::storage::SessionSummary m_session;
    core::derived::SessionLanes m_lanes;
    double m_duration_s = 0.0;
    QCustomPlot* m_plot;
    QLabel* m_readout;
    std::vector<QCPGraph*> m_graphs;
    std::vector<QCPItemText*> m_emptyTexts;  // per lane, shown when it has nothing to draw
    QCPAxisRect* m_markerLane = nullptr;
    std::vector<core::storage::TraceWindow> m_windows;
    std::vector<QCPItemStraightLine*> m_hoverLines, m_cursorLines, m_playheadLines;
    std::optional<double> m_cursor_s;
    QPointF m_pressedAt;       // a release near it is a click, not a drag
    QTimer m_reloadTimer;      // one read per event-loop turn, however many moves
    int m_loadedWidth_px = 0;  // the lane width the shown windows were read for
    bool m_syncing = false;
};

}  // namespace tactiscope::ui
