// LivePlotWidget: frame loop, local history, decimation and lane layout.
#include "ui/plot/LivePlotWidget.h"

#include "core/signal/MinMaxDecimation.h"
#include "core/signal/ScrollingMinMax.h"
#include "ui/common/DisplayUnits.h"
#include "ui/plot/AxisTicks.h"
#include "ui/plot/OpaqueCustomPlot.h"
#include "ui/plot/PixelColumnGraph.h"

#include <QHelpEvent>
#include <QLabel>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace tactiscope::ui {
namespace {

// ~40 frames per second; the timer is single-shot and re-armed after each
// frame, so a slow frame delays the next one instead of queueing more.
constexpr int kFrameInterval_ms = 25;

// Okabe–Ito palette: distinguishable with the common colour-vision deficiencies.
constexpr std::array<QRgb, 8> kTraceColours{0x0072B2, 0xE69F00, 0x009E73, 0xD55E00,
                                            0xCC79A7, 0x56B4E9, 0x000000, 0xF0E442};

// Solid light grid lines: dotted ones look the same at a glance but cost
// the raster engine far more per frame.
void styleGrid(QCPAxisRect* rect)
{
    for (QCPAxis* axis : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)}) {
        axis->grid()->setPen(QPen(QColor(0xe4, 0xe4, 0xe4), 0));
        axis->grid()->setZeroLinePen(QPen(QColor(0xb0, 0xb0, 0xb0), 0));
    }
}

// Tick marks and labels at round values of the time shown (stream time
// minus the origin), placed on the stream's time.
class OffsetTicker : public QCPAxisTicker {
public:
    explicit OffsetTicker(double origin_s)
        : m_origin_s(origin_s)
    {
    }
    void generate(const QCPRange& range, const QLocale& locale, QChar formatChar, int precision, QVector<double>& ticks,
                  QVector<double>* subTicks, QVector<QString>* tickLabels) override
    {
        QCPAxisTicker::generate(QCPRange(range.lower - m_origin_s, range.upper - m_origin_s), locale, formatChar,
                                precision, ticks, subTicks, tickLabels);
        for (double& tick : ticks) tick += m_origin_s;
        if (subTicks)
            for (double& tick : *subTicks) tick += m_origin_s;
    }

private:
    double m_origin_s;
};

}  // namespace

LivePlotWidget::LivePlotWidget(QWidget* parent)
    : QWidget(parent),
      m_plot(new OpaqueCustomPlot(this))
{
    m_plot->installEventFilter(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 0);
    layout->setSpacing(2);
    auto* banner = new QLabel(tr("Paused: acquisition and recording go on. Drag or wheel the time axis to look back; "
                                 "resume to follow the newest samples."),
                              this);
    banner->setObjectName(QStringLiteral("pausedBanner"));
    banner->setWordWrap(true);
    banner->setStyleSheet(QStringLiteral("QLabel { background: #fff3cd; color: #5c4400; padding: 4px 8px; "
                                         "border-radius: 4px; }"));
    banner->hide();
    m_pausedBanner = banner;
    layout->addWidget(banner);
    layout->addWidget(m_plot, 1);

    m_laneMargins = new QCPMarginGroup(m_plot);
    // Each trace as one polyline, not a line call per segment (QCustomPlot's
    // "fast polylines"): for thin unsmoothed pens the raster engine strokes
    // a whole polyline faster (measured: bench/LiveDisplayBenchmark).
    m_plot->setPlottingHint(QCP::phFastPolylines, false);
    // One paint buffer, not a second for the overlay layer (nothing is drawn
    // there): each frame clears and composes one full-size image less.
    m_plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    // Thin unsmoothed traces draw several times faster; text stays smooth.
    m_plot->setNotAntialiasedElements(QCP::aePlottables | QCP::aeGrid | QCP::aeSubGrid | QCP::aeZeroLine);
    m_plot->setNoAntialiasingOnDrag(true);
    // One row, small type, thin frame: in a lane a hundred pixels high the
    // legend must not hide the first second of the traces.
    m_plot->legend->setVisible(false);  // shown once traces share a lane: never an empty box
    m_plot->legend->setBrush(QColor(255, 255, 255, 200));
    m_plot->legend->setBorderPen(QPen(QColor(0, 0, 0, 60)));
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setWrap(0);
    m_plot->legend->setColumnSpacing(10);
    m_plot->legend->setMargins(QMargins(5, 3, 6, 3));
    QFont legendFont = font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.85);
    m_plot->legend->setFont(legendFont);
    // An icon lower than the text lets QCustomPlot cut the item box short
    // and clip a descender ("g", "y"); a line's height keeps it whole.
    m_plot->legend->setIconSize(18, QFontMetrics(legendFont).height() + 2);
    moveLegendTo(m_plot->axisRect());
    m_timeLabel = tr("Time since connect (s)");
    applyTimeAxis(m_plot->axisRect());
    m_plot->xAxis->setRange(0.0, m_window_s);

    m_frameTimer.setSingleShot(true);
    m_frameTimer.setInterval(kFrameInterval_ms);
    connect(&m_frameTimer, &QTimer::timeout, this, &LivePlotWidget::refresh);
}

LivePlotWidget::~LivePlotWidget() = default;

void LivePlotWidget::setSource(std::shared_ptr<const core::LiveBuffer> buffer,
                               const std::vector<core::ChannelDescriptor>& channels, double sampleRate_hz,
                               std::vector<DisplayUnit> units)
{
    clearSource();
    // The buffer may hold channels a board began to print since `channels`.
    if (!buffer || channels.size() > buffer->channelCount() || !(sampleRate_hz > 0.0)) return;
    if (units.size() != channels.size()) {
        units.clear();
        for (const auto& channel : channels) units.push_back(displayUnitFor(channel));
    }

    m_buffer = std::move(buffer);
    m_sampleRate_hz = sampleRate_hz;
    // The longest window and then some, for scrolling back while paused.
    const auto capacity = static_cast<std::size_t>(std::ceil(sampleRate_hz * kHistory_s));
    m_time = std::make_unique<core::RingBuffer<double>>(capacity);
    m_values.assign(channels.size(), core::RingBuffer<double>(capacity));
    buildPlotItems(channels, units);
    drawMarkers();
    scheduleFrame();
}

void LivePlotWidget::showMoreChannels(const std::vector<core::ChannelDescriptor>& channels)
{
    if (!m_buffer || channels.size() <= m_values.size() || channels.size() > m_buffer->channelCount()) return;
    std::vector<DisplayUnit> units;
    for (const auto& channel : channels) units.push_back(displayUnitFor(channel));
    // The new traces begin where the history stands: holes before.
    while (m_values.size() < channels.size()) {
        m_values.emplace_back(m_time->capacity());
        m_values.back().fillTo(m_time->endIndex(), std::numeric_limits<double>::quiet_NaN());
    }
    m_scrolling.clear();
    removePlotItems();
    buildPlotItems(channels, units);
    drawMarkers();
    m_viewChanged = true;
    scheduleFrame();
}

void LivePlotWidget::clearSource()
{
    m_frameTimer.stop();
    m_markers.clear();
    m_buffer.reset();
    m_cursor = {};
    m_time.reset();
    m_values.clear();
    m_scrolling.clear();
    removePlotItems();
    m_plot->replot();
}

void LivePlotWidget::setWindowLength(double seconds)
{
    if (!(seconds > 0.0)) return;
    m_window_s = std::min(seconds, kMaxWindow_s);
}

int LivePlotWidget::drawnPointCount(std::size_t channel) const
{
    return channel < m_graphs.size() ? m_graphs[channel]->dataCount() : 0;
}

void LivePlotWidget::buildPlotItems(const std::vector<core::ChannelDescriptor>& channels,
                                    const std::vector<DisplayUnit>& units)
{
    std::vector<DisplayUnit> laneUnits;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        const DisplayUnit& unit = units[c];
        auto found = std::find(laneUnits.begin(), laneUnits.end(), unit);
        const auto lane = static_cast<std::size_t>(found - laneUnits.begin());
        if (found == laneUnits.end()) {
            laneUnits.push_back(unit);
            // Lane 0 reuses the plot's default axis rect (it owns the legend).
            QCPAxisRect* rect = m_plot->axisRect();
            if (lane > 0) {
                rect = new QCPAxisRect(m_plot);
                m_plot->plotLayout()->addElement(static_cast<int>(lane), 0, rect);
            }
            applyTimeAxis(rect);
            rect->setMarginGroup(QCP::msLeft | QCP::msRight, m_laneMargins);
            styleGrid(rect);
            connect(rect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                    &LivePlotWidget::syncTimeAxes, Qt::UniqueConnection);
            rect->axis(QCPAxis::atLeft)->setLabel(unit.axisTitle());
            useEvenDecimals(*rect->axis(QCPAxis::atLeft));
            m_lanes.push_back({rect, {0.0, 0.0}, unit.scale, std::nullopt, nullptr, std::nullopt});
            if (!unit.levels.empty()) {  // a lane of named levels reads as its names, as in the review
                QSharedPointer<QCPAxisTickerText> named(new QCPAxisTickerText);
                for (const auto& [value, name] : unit.levels) named->addTick(value, name);
                rect->axis(QCPAxis::atLeft)->setTicker(named);
                m_lanes.back().levels = AxisRange{unit.levels.front().first - 0.4, unit.levels.back().first + 0.4};
            }
        }
        QCPAxisRect* rect = m_lanes[lane].rect;
        QCPGraph* graph = new PixelColumnGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        graph->setName(QString::fromStdString(channels[c].name));
        graph->setPen(QPen(QColor(kTraceColours[c % kTraceColours.size()]), 1.0));
        graph->setAdaptiveSampling(false);  // we decimate ourselves
        m_graphs.push_back(graph);
        m_graphLane.push_back(lane);
        m_graphScale.push_back(unit.scale);
    }
    // A lane of one trace is named by its axis title; the legend names the
    // traces that share a lane, sits in the first such lane, and is hidden
    // when none do.
    std::optional<std::size_t> sharedLane;
    for (std::size_t c = 0; c < m_graphs.size(); ++c) {
        if (std::count(m_graphLane.begin(), m_graphLane.end(), m_graphLane[c]) > 1) {
            if (!sharedLane) sharedLane = m_graphLane[c];
        } else {
            m_graphs[c]->removeFromLegend();
        }
    }
    if (sharedLane) moveLegendTo(m_lanes[*sharedLane].rect);
    m_plot->legend->setVisible(sharedLane.has_value());
    // The lane the legend sits over gets the room of two, its traces the
    // room left under the legend (issue 52: 40 px under seven entries).
    for (std::size_t lane = 0; lane < m_lanes.size(); ++lane)
        m_plot->plotLayout()->setRowStretchFactor(static_cast<int>(lane), sharedLane == lane ? 2.0 : 1.0);
    updateInteractions();
}

void LivePlotWidget::moveLegendTo(QCPAxisRect* rect)
{
    if (auto* inset = qobject_cast<QCPLayoutInset*>(m_plot->legend->layout())) inset->take(m_plot->legend);
    // Top left: the newest samples arrive at the right and must stay visible.
    rect->insetLayout()->addElement(m_plot->legend, Qt::AlignTop | Qt::AlignLeft);
}

// The legend sits over the top of its lane: the lane's range is raised by
// this fraction so no trace runs under it (a press's peak did).
double LivePlotWidget::legendHeadroom(const QCPAxisRect* rect) const
{
    if (!m_plot->legend->visible() || m_plot->legend->layout() != rect->insetLayout()) return 0.0;
    // From the lane's top to the legend's bottom (its inset margin
    // included); before the first layout, its size hint and a margin.
    const QRect legend = m_plot->legend->outerRect();
    const int legend_px =
        std::max(legend.bottom() - rect->top(), m_plot->legend->minimumOuterSizeHint().height() + 12) + 2;
    const int free_px = rect->height() - legend_px;
    return free_px > legend_px ? static_cast<double>(legend_px) / free_px : 0.0;
}

void LivePlotWidget::removePlotItems()
{
    for (Lane& lane : m_lanes)
        if (lane.thresholdLine) m_plot->removeItem(lane.thresholdLine);
    for (QCPAbstractItem* item : m_markerItems) m_plot->removeItem(item);
    m_markerItems.clear();
    for (QCPItemRect* band : m_gapBands) m_plot->removeItem(band);
    m_gapBands.clear();
    m_gaps.clear();
    moveLegendTo(m_plot->axisRect());  // out of the lanes about to go
    m_plot->clearGraphs();
    // Extra lanes live in rows 1.. of the layout; row 0 is the default rect.
    for (int row = m_plot->plotLayout()->rowCount() - 1; row > 0; --row) {
        m_plot->plotLayout()->remove(m_plot->plotLayout()->element(row, 0));
    }
    m_plot->plotLayout()->simplify();
    m_plot->axisRect()->setMarginGroup(QCP::msLeft | QCP::msRight, nullptr);
    m_lanes.clear();
    m_plot->legend->setVisible(false);
    m_graphs.clear();
    m_graphLane.clear();
    m_graphScale.clear();
}

void LivePlotWidget::scheduleFrame()
{
    if (m_buffer) m_frameTimer.start();
}

std::uint64_t LivePlotWidget::firstIndexAtOrAfter(double t_s) const
{
    std::uint64_t lo = m_time->oldestIndex();
    std::uint64_t hi = m_time->endIndex();
    while (lo < hi) {
        const std::uint64_t mid = lo + (hi - lo) / 2;
        if (m_time->at(mid) < t_s)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

void LivePlotWidget::setPaused(bool paused)
{
    m_paused = paused;
    m_pausedBanner->setVisible(paused && m_showsBanner);
    m_viewChanged = true;
    updateInteractions();
}

void LivePlotWidget::setScaleHeld(bool held)
{
    m_scaleHeld = held;
    updateInteractions();
}

// Live, the time axis belongs to the stream; paused, to the user. A held
// value axis is the user's too.
void LivePlotWidget::updateInteractions()
{
    Qt::Orientations drag;
    if (m_paused) drag |= Qt::Horizontal;
    if (m_scaleHeld) drag |= Qt::Vertical;
    m_plot->setInteractions(drag ? QCP::Interactions(QCP::iRangeDrag | QCP::iRangeZoom) : QCP::Interactions());
    for (const Lane& lane : m_lanes) {
        lane.rect->setRangeDrag(drag);
        lane.rect->setRangeZoom(drag);
    }
}

std::pair<double, double> LivePlotWidget::valueRange(std::size_t lane) const
{
    const QCPRange range = m_lanes.at(lane).rect->axis(QCPAxis::atLeft)->range();
    return {range.lower, range.upper};
}

std::pair<double, double> LivePlotWidget::visibleTimeRange() const
{
    const QCPRange range = m_plot->xAxis->range();
    return {range.lower, range.upper};
}

void LivePlotWidget::scrollTo(double start_s)
{
    if (!m_paused) return;
    m_plot->xAxis->setRange(start_s, start_s + m_plot->xAxis->range().size());
}

void LivePlotWidget::followTimeRange(double start_s, double end_s)
{
    if (!m_paused) return;
    m_following = true;
    m_plot->xAxis->setRange(start_s, end_s);
    m_following = false;
}

void LivePlotWidget::setThreshold(std::size_t lane, std::optional<double> value_si)
{
    if (lane >= m_lanes.size()) return;
    Lane& l = m_lanes[lane];
    l.threshold_si = value_si;
    if (l.thresholdLine) {
        m_plot->removeItem(l.thresholdLine);
        l.thresholdLine = nullptr;
    }
    if (value_si) {
        auto* line = new QCPItemStraightLine(m_plot);
        line->setClipAxisRect(l.rect);
        for (QCPItemPosition* point : {line->point1, line->point2})
            point->setAxes(l.rect->axis(QCPAxis::atBottom), l.rect->axis(QCPAxis::atLeft));
        // Two points at the same value, any two times: the line is horizontal.
        line->point1->setCoords(0.0, *value_si * l.scale);
        line->point2->setCoords(1.0, *value_si * l.scale);
        line->setPen(QPen(QColor(QRgb(kThresholdRgb)), 1.0, Qt::DashLine));
        line->setSelectable(false);
        l.thresholdLine = line;
    }
    m_viewChanged = true;
    m_plot->replot();
}

std::optional<double> LivePlotWidget::threshold(std::size_t lane) const
{
    return lane < m_lanes.size() ? m_lanes[lane].threshold_si : std::nullopt;
}

void LivePlotWidget::setPausedBannerShown(bool shown)
{
    m_showsBanner = shown;
    m_pausedBanner->setVisible(m_paused && shown);
}

void LivePlotWidget::applyTimeAxis(QCPAxisRect* rect)
{
    QCPAxis* axis = rect->axis(QCPAxis::atBottom);
    axis->setTicker(QSharedPointer<QCPAxisTicker>(new OffsetTicker(m_origin_s)));
    axis->setLabel(m_compactTimeTitle ? tr("t (s)") : m_timeLabel);
}

void LivePlotWidget::setCompactTimeTitle(bool compact)
{
    m_compactTimeTitle = compact;
    applyTimeAxis(m_plot->axisRect());
    for (const Lane& lane : m_lanes) applyTimeAxis(lane.rect);
}

void LivePlotWidget::setTimeOrigin(double origin_s, const QString& label)
{
    if (origin_s == m_origin_s && label == m_timeLabel) return;
    m_origin_s = origin_s;
    m_timeLabel = label;
    applyTimeAxis(m_plot->axisRect());
    for (const Lane& lane : m_lanes) applyTimeAxis(lane.rect);
    m_viewChanged = true;
    m_plot->replot();
}

QString LivePlotWidget::timeAxisLabel() const
{
    return m_timeLabel;
}

void LivePlotWidget::addMarker(double t_s, const QString& note)
{
    m_markers.push_back({t_s, note, false});
    drawMarkers();
    m_plot->replot();
}

std::size_t LivePlotWidget::markerCount() const
{
    return static_cast<std::size_t>(std::ranges::count(m_markers, false, &Marker::event));
}

void LivePlotWidget::addEvent(double t_s, const QString& text)
{
    // What the history no longer holds cannot be scrolled to: its items go,
    // so a long shift does not pile them up.
    std::erase_if(m_markers, [t_s](const Marker& m) { return m.t_s < t_s - kHistory_s; });
    m_markers.push_back({t_s, text, true});
    drawMarkers();
    m_plot->replot();
}

void LivePlotWidget::clearEvents()
{
    std::erase_if(m_markers, [](const Marker& m) { return m.event; });
    drawMarkers();
    m_plot->replot();
}

std::size_t LivePlotWidget::eventCount() const
{
    return m_markers.size() - markerCount();
}

// A line per marker in every lane — dashed purple for the operator's,
// solid red for the detector's events — its text at the top of the first.
void LivePlotWidget::drawMarkers()
{
    for (QCPAbstractItem* item : m_markerItems) m_plot->removeItem(item);
    m_markerItems.clear();
    const QPen markerPen(QColor(0x6a, 0x3d, 0x9a), 1.0, Qt::DashLine);
    const QPen eventPen(QColor(0xc6, 0x28, 0x28, 150), 1.0, Qt::SolidLine);
    for (const Marker& marker : m_markers) {
        const QPen& pen = marker.event ? eventPen : markerPen;
        for (std::size_t l = 0; l < m_lanes.size(); ++l) {
            QCPAxisRect* rect = m_lanes[l].rect;
            auto* line = new QCPItemStraightLine(m_plot);
            line->setLayer(QStringLiteral("grid"));
            line->setPen(pen);
            line->setClipAxisRect(rect);
            for (QCPItemPosition* point : {line->point1, line->point2}) {
                point->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                point->setAxisRect(rect);
                point->setTypeX(QCPItemPosition::ptPlotCoords);
                point->setTypeY(QCPItemPosition::ptAxisRectRatio);
            }
            line->point1->setCoords(marker.t_s, 0.0);
            line->point2->setCoords(marker.t_s, 1.0);
            m_markerItems.push_back(line);
            if (l != 0 || marker.note.isEmpty()) continue;
            auto* label = new QCPItemText(m_plot);
            label->setClipAxisRect(rect);
            label->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            label->position->setAxisRect(rect);
            label->position->setTypeX(QCPItemPosition::ptPlotCoords);
            label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
            // Markers' notes at the top, events' at the bottom: apart, and
            // clear of the legend in the top left.
            label->position->setCoords(marker.t_s, marker.event ? 1.0 : 0.0);
            // Right of its line in the left half of the lane, left of it in
            // the right half: a note placed at "now" ran off the lane's edge.
            const QCPRange shown = rect->axis(QCPAxis::atBottom)->range();
            const bool rightHalf = marker.t_s > shown.center();
            label->setPositionAlignment((rightHalf ? Qt::AlignRight : Qt::AlignLeft) |
                                        (marker.event ? Qt::AlignBottom : Qt::AlignTop));
            label->setPadding(QMargins(3, 1, 3, 1));
            label->setBrush(QColor(255, 255, 255, 210));
            label->setColor(QColor(pen.color().rgb()));  // the text opaque
            label->setText(QFontMetrics(font()).elidedText(marker.note, Qt::ElideRight, 160));
            label->setProperty("note", marker.note);
            m_markerItems.push_back(label);
        }
    }
}

bool LivePlotWidget::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_plot || event->type() != QEvent::ToolTip) return QWidget::eventFilter(watched, event);
    const auto* help = static_cast<QHelpEvent*>(event);
    for (QCPAbstractItem* item : m_markerItems) {
        auto* label = qobject_cast<QCPItemText*>(item);
        if (!label) continue;
        const QRectF box(label->topLeft->pixelPosition(), label->bottomRight->pixelPosition());
        if (!box.contains(help->pos())) continue;
        QToolTip::showText(help->globalPos(), label->property("note").toString(), m_plot, box.toAlignedRect());
        return true;
    }
    QToolTip::hideText();
    return true;
}

// One lane's time axis moved (a drag, a zoom): every lane follows, and a
// paused view is redrawn from the history at the next frame.
void LivePlotWidget::syncTimeAxes(const QCPRange& range)
{
    if (m_drawing) return;
    const QCPRange clamped(range.lower, range.lower + std::min(range.size(), kMaxWindow_s));
    m_drawing = true;
    for (const Lane& lane : m_lanes) lane.rect->axis(QCPAxis::atBottom)->setRange(clamped);
    m_drawing = false;
    m_viewChanged = true;
    if (m_paused && !m_following) emit userScrolled(clamped.lower, clamped.upper);
}

void LivePlotWidget::refresh()
{
    if (!m_buffer) return;
    // The history fills while paused too, so resuming shows no hole.
    const bool arrived = m_buffer->readNew(m_cursor, m_chunk) > 0;
    if (arrived) {
        m_time->push(std::span<const double>(m_chunk.time_s));
        for (std::size_t c = 0; c < m_values.size(); ++c) m_values[c].push(std::span<const double>(m_chunk.values[c]));
    }
    if (m_time->size() == 0 || (!arrived && !m_viewChanged) || (m_paused && !m_viewChanged)) {
        scheduleFrame();
        return;
    }
    if (m_paused) {
        m_scrolling.clear();  // resuming rebuilds it for the newest window
        const QCPRange range = m_plot->xAxis->range();
        draw(range.lower, range.upper);
    } else {
        // Until a full window has arrived the traces grow from the left edge;
        // after that the window scrolls with the newest sample at the right.
        const double latest_s = m_time->at(m_time->endIndex() - 1);
        const double oldest_s = m_time->at(m_time->oldestIndex());
        const double start_s = std::max(latest_s - m_window_s, std::min(oldest_s, m_growsFrom_s.value_or(oldest_s)));
        followLive(start_s, arrived);
        draw(start_s, start_s + m_window_s);
    }
    m_viewChanged = false;
    scheduleFrame();
}

// Live, each frame decimates only the samples that arrived (ScrollingMinMax);
// a new column width (a resize, another window length) or a resume starts
// over from the history.
void LivePlotWidget::followLive(double start_s, bool arrived)
{
    const int width_px = std::max(1, m_plot->axisRect()->width());
    const double columnWidth_s = m_window_s / width_px;
    if (m_scrolling.empty() || m_scrolling.front().columnWidth_s() != columnWidth_s) {
        m_scrolling.assign(m_values.size(), core::signal::ScrollingMinMax(columnWidth_s));
        const std::uint64_t first = firstIndexAtOrAfter(start_s - columnWidth_s);
        const auto count = static_cast<std::size_t>(m_time->endIndex() - first);
        m_visibleTime.resize(count);
        m_time->copy(first, m_visibleTime);
        for (std::size_t c = 0; c < m_values.size(); ++c) {
            m_visibleValues.resize(count);
            m_values[c].copy(first, m_visibleValues);
            m_scrolling[c].append(m_visibleTime, m_visibleValues);
        }
    } else if (arrived) {
        for (std::size_t c = 0; c < m_values.size(); ++c) m_scrolling[c].append(m_chunk.time_s, m_chunk.values[c]);
    }
    for (auto& trace : m_scrolling) trace.dropBefore(start_s);
}

// The points of channel c between start_s and end_s, min/max per column.
void LivePlotWidget::decimatedPoints(std::size_t c, double start_s, double end_s)
{
    if (!m_scrolling.empty()) {
        m_scrolling[c].points(m_decimatedTime, m_decimatedValues);
        return;
    }
    // The samples in view and one either side, so lines reach the edges.
    std::uint64_t first = firstIndexAtOrAfter(start_s);
    if (first > m_time->oldestIndex()) --first;
    const std::uint64_t end = std::min(firstIndexAtOrAfter(end_s) + 1, m_time->endIndex());
    const auto count = static_cast<std::size_t>(end > first ? end - first : 0);
    m_visibleTime.resize(count);
    m_visibleValues.resize(count);
    if (count > 0) {
        m_time->copy(first, m_visibleTime);
        m_values[c].copy(first, m_visibleValues);
    }
    const int width_px = std::max(1, m_plot->axisRect()->width());
    const double columnWidth_s = std::max(end_s - start_s, 1e-9) / width_px;
    core::signal::decimateMinMax(m_visibleTime, m_visibleValues, columnWidth_s, m_decimatedTime, m_decimatedValues);
}

void LivePlotWidget::draw(double start_s, double end_s)
{
    std::vector<double> laneMin(m_lanes.size(), std::numeric_limits<double>::infinity());
    std::vector<double> laneMax(m_lanes.size(), -std::numeric_limits<double>::infinity());
    // Consecutive points are less than two columns apart (and, when every
    // sample is drawn, one sample period): a longer step is lost samples.
    const int width_px = std::max(1, m_plot->axisRect()->width());
    const double maxStep_s = std::max(2.0 * (end_s - start_s) / width_px, 1.5 / m_sampleRate_hz);
    for (std::size_t c = 0; c < m_graphs.size(); ++c) {
        decimatedPoints(c, start_s, end_s);
        if (c == 0) {
            m_gaps = core::signal::gapsIn(m_decimatedTime, maxStep_s);
            // A probe away longer than the window: its first samples back
            // start mid-view, and what came before lies beyond the left
            // edge, so the gap reaches back to that edge.
            if (!m_decimatedTime.empty() && m_decimatedTime.front() - start_s > maxStep_s &&
                firstIndexAtOrAfter(start_s) > m_time->oldestIndex())
                m_gaps.insert(m_gaps.begin(), {start_s, m_decimatedTime.front()});
        }
        core::signal::breakAtGaps(m_decimatedTime, m_decimatedValues, maxStep_s);
        QVector<double> keys(m_decimatedTime.begin(), m_decimatedTime.end());
        QVector<double> values(static_cast<qsizetype>(m_decimatedValues.size()));
        const double scale = m_graphScale[c];
        for (std::size_t i = 0; i < m_decimatedValues.size(); ++i) {
            values[static_cast<qsizetype>(i)] = m_decimatedValues[i] * scale;
        }
        // NaN (no value there) takes no part in the lane's range.
        const std::size_t lane = m_graphLane[c];
        for (const double v : values) {
            if (std::isnan(v)) continue;
            laneMin[lane] = std::min(laneMin[lane], v);
            laneMax[lane] = std::max(laneMax[lane], v);
        }
        m_graphs[c]->setData(keys, values, true);
    }

    m_drawing = true;
    for (std::size_t lane = 0; lane < m_lanes.size(); ++lane) {
        Lane& l = m_lanes[lane];
        l.rect->axis(QCPAxis::atBottom)->setRange(start_s, end_s);
        if (l.threshold_si) {  // the line it is read against stays in view
            laneMin[lane] = std::min(laneMin[lane], *l.threshold_si * l.scale);
            laneMax[lane] = std::max(laneMax[lane], *l.threshold_si * l.scale);
        }
        if (l.levels) {
            laneMin[lane] = std::min(laneMin[lane], l.levels->lower);
            laneMax[lane] = std::max(laneMax[lane], l.levels->upper);
        }
        if (m_scaleHeld || !std::isfinite(laneMin[lane])) continue;
        l.range = nextAxisRange(l.range, laneMin[lane], laneMax[lane]);
        const double headroom = legendHeadroom(l.rect);
        l.rect->axis(QCPAxis::atLeft)->setRange(l.range.lower, l.range.upper + headroom * l.range.size());
    }
    // About one tick label per 40 px, so low lanes stay legible, and two at least.
    for (Lane& l : m_lanes)
        fitTickCount(*l.rect->axis(QCPAxis::atLeft), l.rect->height(), QFontMetrics(font()).height(),
                     std::clamp(l.rect->height() / 40, 2, 6));
    m_drawing = false;
    drawGapBands();
    m_plot->replot();
    ++m_framesDrawn;
}

// A grey band over each gap in every lane, under the traces.
void LivePlotWidget::drawGapBands()
{
    const std::size_t wanted = m_gaps.size() * m_lanes.size();
    while (m_gapBands.size() > wanted) {
        m_plot->removeItem(m_gapBands.back());
        m_gapBands.pop_back();
    }
    for (std::size_t i = 0; i < wanted; ++i) {
        const Lane& lane = m_lanes[i % m_lanes.size()];
        const core::signal::TimeGap& gap = m_gaps[i / m_lanes.size()];
        if (i == m_gapBands.size()) {
            auto* band = new QCPItemRect(m_plot);
            band->setLayer(QStringLiteral("grid"));
            band->setPen(Qt::NoPen);
            band->setBrush(QColor(0, 0, 0, 28));
            band->setSelectable(false);
            m_gapBands.push_back(band);
        }
        QCPItemRect* band = m_gapBands[i];
        band->setClipAxisRect(lane.rect);
        for (QCPItemPosition* corner : {band->topLeft, band->bottomRight}) {
            corner->setAxes(lane.rect->axis(QCPAxis::atBottom), lane.rect->axis(QCPAxis::atLeft));
            corner->setAxisRect(lane.rect);
            corner->setTypeX(QCPItemPosition::ptPlotCoords);
            corner->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        band->topLeft->setCoords(gap.from_s, 0.0);
        band->bottomRight->setCoords(gap.to_s, 1.0);
    }
}

}  // namespace tactiscope::ui
