// ReviewPlot: lanes read window by window from the store, a marker lane,
// the hover readout, the pinned cursor and the replay playhead.
#include "ui/review/ReviewPlot.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/plot/AxisTicks.h"
#include "ui/report/LaneAxis.h"
#include "ui/report/PlotImage.h"

#include <QFontMetrics>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

const QColor kTrace(31, 119, 180);
const QColor kGap(160, 160, 160, 90);
constexpr int kMarkerRowHeight_px = 20;
// A value lane keeps this many text lines of height: its name (written
// along the axis) and three ticks a label apart. Below that the labels
// would overlap, so the lanes scroll instead.
constexpr int kLaneLines = 5;
constexpr double kMinimumSamplesShown = 10.0;

// x in seconds on the lane's time axis, y as a fraction of the lane's height.
void placeInLane(QCPItemPosition* position, QCPAxisRect* rect, double time_s, double heightRatio)
{
    position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    position->setAxisRect(rect);
    position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    position->setCoords(time_s, heightRatio);
}

// A readout value with the decimals of five significant digits at
// `magnitude` (display units), so a stretch's minimum and maximum match.
// A lane's axis title that fits beside it: a part's device (its lane's,
// which leads its quantity as "DEVICE/") on a line of its own ("beam" over
// "Deflection" over "(mm)"), each line elided to the lane's height, so no
// title runs into the next lane's (issue 52).
QString fittedLaneLabel(DisplayUnit unit, const std::string& device, const QFont& font, int height_px)
{
    QStringList lines;
    if (!device.empty()) {
        lines << QString::fromStdString(device);
        unit.quantity.remove(0, static_cast<qsizetype>(device.size()) + 1);
    }
    lines << laneLabel(unit).split(QLatin1Char('\n'));
    const QFontMetrics metrics(font);
    for (QString& line : lines) line = metrics.elidedText(line, Qt::ElideRight, std::max(height_px - 4, 12));
    return lines.join(QLatin1Char('\n'));
}

QString valueText(double value, const DisplayUnit& unit, double magnitude)
{
    return fixedText(value * unit.scale, unit.decimals.value_or(decimalsForMagnitude(magnitude, 5)));
}

// A lane of named levels (the detector's decision) reads as its names,
// never as the numbers they are drawn at ("0.0000 … 0.0000" for "none").
QString levelName(double value, const DisplayUnit& unit)
{
    const auto nearest = std::ranges::min_element(
        unit.levels, {}, [&](const auto& level) { return std::abs(level.first - value * unit.scale); });
    return nearest->second;
}

}  // namespace

ReviewPlot::ReviewPlot(core::storage::SessionSource& store, const core::storage::SessionSummary& session,
                       const core::derived::LaneOptions& options, QWidget* parent)
    : QWidget(parent),
      m_store(store),
      m_session(session),
      m_lanes(core::derived::sessionLanes(store, session, options)),
      m_duration_s(session.duration_s()),
      m_plot(new QCustomPlot(this)),
      m_readout(new QLabel(this)),
      m_windows(m_lanes.lanes.size())
{
    m_plot->setObjectName(QStringLiteral("reviewPlot"));
    m_readout->setObjectName(QStringLiteral("cursorReadout"));
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setText(tr("Point at the plot for a readout; click to pin the cursor; drag or wheel to move in "
                          "time; Home shows the whole session."));
    m_plot->plotLayout()->clear();
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->setNoAntialiasingOnDrag(true);
    auto* margins = new QCPMarginGroup(m_plot);
    const auto gaps = store.gaps(session.id);
    const double rate_hz = session.sampleRate_hz;
    for (std::size_t c = 0; c <= m_lanes.lanes.size(); ++c) {
        auto* rect = new QCPAxisRect(m_plot);
        m_plot->plotLayout()->addElement(static_cast<int>(c), 0, rect);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->setRangeDrag(Qt::Horizontal);
        rect->setRangeZoom(Qt::Horizontal);
        QCPAxis* time = rect->axis(QCPAxis::atBottom);
        connect(time, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this, rect] { syncRange(rect); });
        if (c == m_lanes.lanes.size()) {
            m_markerLane = rect;
            time->setLabel(tr("Time from the session start (s)"));
            rect->axis(QCPAxis::atLeft)->setRangeReversed(true);
            rect->axis(QCPAxis::atLeft)->grid()->setVisible(false);
            break;
        }
        time->setTickLabels(false);
        setUpLaneAxis(*rect, unitOf(c), m_lanes.lanes[c]->threshold());
        rect->setSizeConstraintRect(QCPLayoutElement::scrInnerRect);  // the lane itself, not its margins
        rect->setMinimumSize(0, kLaneLines * laneLine());
        QCPGraph* graph = m_plot->addGraph(time, rect->axis(QCPAxis::atLeft));
        graph->setPen(QPen(kTrace, 1.0));
        m_graphs.push_back(graph);
        // A quantity with no overview (computed from exact samples only) says how to see it.
        auto* zoomIn = new QCPItemText(m_plot);
        zoomIn->setClipAxisRect(rect);
        zoomIn->position->setType(QCPItemPosition::ptAxisRectRatio);
        zoomIn->position->setAxisRect(rect);
        zoomIn->position->setCoords(0.5, 0.5);
        zoomIn->setColor(QColor(90, 90, 90));
        zoomIn->setText(tr("Computed from exact samples only: zoom in to see it"));
        zoomIn->setVisible(false);
        m_emptyTexts.push_back(zoomIn);
        for (const auto& gap : gaps) {
            auto* item = new QCPItemRect(m_plot);
            item->setClipAxisRect(rect);
            placeInLane(item->topLeft, rect, static_cast<double>(gap.firstIndex) / rate_hz, 0.0);
            placeInLane(item->bottomRight, rect, static_cast<double>(gap.firstIndex + gap.count) / rate_hz, 1.0);
            item->setPen(Qt::NoPen);
            item->setBrush(kGap);
        }
    }
    m_hoverLines = makeLines(QPen(QColor(120, 120, 120), 1.0, Qt::DotLine));
    m_cursorLines = makeLines(QPen(QColor(40, 40, 40), 1.5));
    m_playheadLines = makeLines(QPen(QColor(200, 30, 60), 1.5));
    setMarkers({}, {});

    // The lanes scroll when the window is too short for all of them at a
    // readable height, rather than squeezing their labels over each other.
    auto* lanes = new QScrollArea(this);
    lanes->setObjectName(QStringLiteral("laneScroll"));
    lanes->setWidget(m_plot);
    lanes->setWidgetResizable(true);
    lanes->setFrameShape(QFrame::NoFrame);
    lanes->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(lanes, 1);
    layout->addWidget(m_readout);

    m_reloadTimer.setSingleShot(true);
    m_reloadTimer.setInterval(0);
    connect(&m_reloadTimer, &QTimer::timeout, this, &ReviewPlot::reload);
    m_plot->setMouseTracking(true);
    connect(m_plot, &QCustomPlot::mouseMove, this, &ReviewPlot::showHover);
    connect(m_plot, &QCustomPlot::mousePress, this, [this](QMouseEvent* event) { m_pressedAt = event->position(); });
    connect(m_plot, &QCustomPlot::mouseRelease, this, &ReviewPlot::pinCursor);
    // Every replot lays out; only a new width calls for other stretches.
    connect(m_plot, &QCustomPlot::afterLayout, this, [this] {
        if (m_markerLane->width() != m_loadedWidth_px) m_reloadTimer.start();
        fitTickCounts();
    });
    showWholeSession();
}

// Ticks dropped rather than overlapped: each lane gets the most ticks (at
// most the three asked for) whose labels, as the ticker would place them
// for the lane's range and height, stand at least a label's height apart,
// with at least two inside the range when any count gives two. (A lane of
// named levels keeps its names: its least height has room for them.)
// Takes effect at the next replot, queued when something changed.
void ReviewPlot::fitTickCounts()
{
    const double line = laneLine();
    bool changed = false;
    for (QCPAxisRect* rect : m_plot->axisRects())
        if (rect != m_markerLane)
            changed = fitTickCount(*rect->axis(QCPAxis::atLeft), rect->height(), line, 3) || changed;
    // The plot is never shorter than its lanes at their least heights with
    // the margins the layout found: below that, the lanes scroll.
    const int least = m_plot->plotLayout()->minimumOuterSizeHint().height();
    if (least > m_plot->minimumHeight()) {
        m_plot->setMinimumHeight(least);
        changed = true;
    }
    if (changed) m_plot->replot(QCustomPlot::rpQueuedReplot);
}

int ReviewPlot::laneLine() const
{
    return QFontMetrics(m_plot->font()).height();  // the axes' tick labels use the plot's font
}

DisplayUnit ReviewPlot::unitOf(std::size_t lane) const
{
    // A part's lane, DEVICE/NAME, in its own mode's units, titled after its device.
    auto descriptor = m_lanes.lanes[lane]->descriptor();
    const std::string& device = m_lanes.devices.at(lane);
    if (device.empty()) return laneUnit(descriptor, m_lanes.modes.at(lane));
    descriptor.name.erase(0, device.size() + 1);
    DisplayUnit unit = laneUnit(descriptor, m_lanes.modes.at(lane));
    unit.quantity.prepend(QString::fromStdString(device + "/"));
    return unit;
}

std::vector<std::string> ReviewPlot::laneNames() const
{
    std::vector<std::string> names;
    for (const auto& lane : m_lanes.lanes) names.push_back(lane->descriptor().name);
    return names;
}

std::vector<QCPItemStraightLine*> ReviewPlot::makeLines(const QPen& pen)
{
    std::vector<QCPItemStraightLine*> lines;
    for (QCPAxisRect* rect : m_plot->axisRects()) {
        auto* line = new QCPItemStraightLine(m_plot);
        line->setClipAxisRect(rect);
        line->setPen(pen);
        line->setVisible(false);
        line->setSelectable(false);
        lines.push_back(line);
    }
    return lines;
}

void ReviewPlot::placeLines(std::vector<QCPItemStraightLine*>& lines, std::optional<double> time_s)
{
    const auto rects = m_plot->axisRects();
    for (std::size_t i = 0; i < lines.size(); ++i) {
        lines[i]->setVisible(time_s.has_value());
        if (!time_s) continue;
        placeInLane(lines[i]->point1, rects[static_cast<int>(i)], *time_s, 0.0);
        placeInLane(lines[i]->point2, rects[static_cast<int>(i)], *time_s, 1.0);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void ReviewPlot::setMarkers(const QStringList& rows, const std::vector<MarkerSpan>& spans)
{
    for (QCPAbstractItem* item : m_markerLane->items())
        if (auto* rect = qobject_cast<QCPItemRect*>(item)) m_plot->removeItem(rect);
    QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
    for (int row = 0; row < rows.size(); ++row) ticker->addTick(row, rows[row]);
    QCPAxis* rowAxis = m_markerLane->axis(QCPAxis::atLeft);
    rowAxis->setTicker(ticker);
    const int count = std::max<int>(1, static_cast<int>(rows.size()));
    rowAxis->setRange(-0.5, count - 0.5);
    m_markerLane->setMinimumSize(0, count * kMarkerRowHeight_px);
    m_markerLane->setMaximumSize(QWIDGETSIZE_MAX, count * kMarkerRowHeight_px);
    // The plot's least height: every lane at its own, with room for the
    // margins between them and the time axis's labels below.
    const int line = laneLine();
    m_plot->setMinimumHeight(static_cast<int>(m_lanes.lanes.size()) * (kLaneLines + 1) * line +
                             count * kMarkerRowHeight_px + 4 * line);
    QCPAxis* time = m_markerLane->axis(QCPAxis::atBottom);
    for (const MarkerSpan& span : spans) {
        auto* item = new QCPItemRect(m_plot);
        item->setClipAxisRect(m_markerLane);
        for (QCPItemPosition* corner : {item->topLeft, item->bottomRight}) {
            corner->setAxes(time, rowAxis);
            corner->setAxisRect(m_markerLane);
        }
        item->topLeft->setCoords(span.start_s, span.row - 0.35);
        item->bottomRight->setCoords(std::max(span.end_s, span.start_s), span.row + 0.35);
        item->setPen(QPen(span.colour.darker(130), 2.0));
        item->setBrush(span.colour);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

double ReviewPlot::from_s() const
{
    return m_markerLane->axis(QCPAxis::atBottom)->range().lower;
}

double ReviewPlot::to_s() const
{
    return m_markerLane->axis(QCPAxis::atBottom)->range().upper;
}

void ReviewPlot::setRange(double from_s, double to_s)
{
    m_markerLane->axis(QCPAxis::atBottom)->setRange(from_s, to_s);
}

void ReviewPlot::showWholeSession()
{
    setRange(0.0, m_duration_s);
}

void ReviewPlot::zoom(double factor)
{
    const double middle = 0.5 * (from_s() + to_s()), half = 0.5 * (to_s() - from_s()) * factor;
    setRange(middle - half, middle + half);
}

void ReviewPlot::centreOn(double time_s, double width_s)
{
    const double half = 0.5 * std::min(width_s, to_s() - from_s());
    setRange(time_s - half, time_s + half);
}

// Every lane follows the one that moved, clipped to the session: at least a
// few samples wide, never past either end.
void ReviewPlot::syncRange(QCPAxisRect* source)
{
    if (m_syncing) return;
    m_syncing = true;
    QCPRange range = source->axis(QCPAxis::atBottom)->range();
    const double minimum = kMinimumSamplesShown / std::max(m_session.sampleRate_hz, 1e-9);
    const double duration = std::max(m_duration_s, minimum);
    double width = std::clamp(range.size(), minimum, duration);
    double lower = std::clamp(range.center() - 0.5 * width, 0.0, duration - width);
    range = QCPRange(lower, lower + width);
    for (QCPAxisRect* rect : m_plot->axisRects()) rect->axis(QCPAxis::atBottom)->setRange(range);
    m_syncing = false;
    emit rangeChanged(range.lower, range.upper);
    m_reloadTimer.start();
}

void ReviewPlot::reload()
{
    m_reloadTimer.stop();
    m_loadedWidth_px = m_markerLane->width();
    // Before the first layout the lanes have no width yet: assume a screen's.
    const std::size_t pixels = static_cast<std::size_t>(m_loadedWidth_px > 10 ? m_loadedWidth_px : 800);
    std::vector<core::storage::TraceWindow> read;
    try {
        for (const auto& lane : m_lanes.lanes)
            read.push_back(core::storage::readTraceWindow(*lane, m_session.sampleRate_hz, m_session.sampleCount,
                                                          from_s(), to_s(), pixels));
    } catch (const core::storage::StorageError& e) {
        // Called from a timer: an exception must not reach the event loop.
        emit readFailed(tr("The samples cannot be read: %1. They are read again when you move or zoom.")
                            .arg(QString::fromStdString(e.what())));
        return;
    }
    emit samplesRead();
    m_windows = std::move(read);
    for (std::size_t c = 0; c < m_lanes.lanes.size(); ++c) {
        const auto& window = m_windows[c];
        const DisplayUnit unit = unitOf(c);
        m_emptyTexts[c]->setVisible(window.t_s.empty());
        QVector<double> keys, values;
        keys.reserve(static_cast<qsizetype>(2 * window.t_s.size()));
        values.reserve(keys.capacity());
        for (std::size_t i = 0; i < window.t_s.size(); ++i) {
            keys << window.t_s[i];
            values << window.low[i] * unit.scale;
            if (window.exact) continue;
            // Min then max at the same time: the line strokes each stretch's span.
            keys << window.t_s[i];
            values << window.high[i] * unit.scale;
        }
        QCPGraph* graph = m_graphs[c];
        graph->setData(keys, values, true);
        QCPAxis* axis = graph->valueAxis();
        axis->setLabel(fittedLaneLabel(unit, m_lanes.devices[c], axis->labelFont(), axis->axisRect()->height()));
        const bool dots = window.exact && static_cast<double>(window.t_s.size()) * 6.0 < static_cast<double>(pixels);
        graph->setScatterStyle(dots ? QCPScatterStyle(QCPScatterStyle::ssDisc, 4) : QCPScatterStyle());
        bool found = false;
        const QCPRange shown = graph->getValueRange(found, QCP::sdBoth, graph->keyAxis()->range());
        fitLaneRange(*graph->valueAxis(), unit, found ? std::optional(shown) : std::nullopt,
                     m_lanes.lanes[c]->threshold());
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QString ReviewPlot::readoutAt(double time_s) const
{
    QStringList parts{tr("t = %1 s").arg(fixedText(time_s, 4))};
    for (std::size_t c = 0; c < m_lanes.lanes.size(); ++c) {
        const auto& window = m_windows[c];
        const auto i = window.nearest(time_s);
        const DisplayUnit unit = unitOf(c);
        const QString& name = unit.quantity;
        if (i < 0) continue;
        const auto k = static_cast<std::size_t>(i);
        if (std::isnan(window.low[k]))
            parts << tr("%1: lost").arg(name);
        else if (!unit.levels.empty()) {
            const QString low = levelName(window.low[k], unit), high = levelName(window.high[k], unit);
            parts << (window.exact || low == high ? tr("%1: %2").arg(name, low)
                                                  : tr("%1: %2 … %3").arg(name, low, high));
        } else if (window.exact)
            parts << tr("%1: %2 %3").arg(name, valueText(window.low[k], unit, window.low[k] * unit.scale), unit.symbol);
        else {
            const double magnitude = std::max(std::abs(window.low[k]), std::abs(window.high[k])) * unit.scale;
            parts << tr("%1: %2 … %3 %4")
                         .arg(name, valueText(window.low[k], unit, magnitude),
                              valueText(window.high[k], unit, magnitude), unit.symbol);
        }
    }
    return parts.join(QStringLiteral("   │   "));
}

void ReviewPlot::showHover(QMouseEvent* event)
{
    const double time_s = m_markerLane->axis(QCPAxis::atBottom)->pixelToCoord(event->position().x());
    if (time_s < from_s() || time_s > to_s()) return;
    m_readout->setText(readoutAt(time_s));
    placeLines(m_hoverLines, time_s);
}

// A click (not the end of a drag) pins the cursor.
void ReviewPlot::pinCursor(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    if ((event->position() - m_pressedAt).manhattanLength() > 3.0) return;
    const double time_s = m_markerLane->axis(QCPAxis::atBottom)->pixelToCoord(event->position().x());
    setCursorTime(time_s);
    emit cursorPinned(time_s);
}

void ReviewPlot::setCursorTime(double time_s)
{
    m_cursor_s = std::clamp(time_s, 0.0, m_duration_s);
    placeLines(m_cursorLines, m_cursor_s);
}

void ReviewPlot::setPlayhead(std::optional<double> time_s)
{
    placeLines(m_playheadLines, time_s);
}

void ReviewPlot::saveImage(const QString& path) const
{
    // The playhead says where a replay was, not what the session holds: the
    // image leaves it out, and the screen keeps it.
    std::vector<bool> shown;
    for (auto* line : m_playheadLines) {
        shown.push_back(line->visible());
        line->setVisible(false);
    }
    const auto restore = [&] {
        for (std::size_t i = 0; i < m_playheadLines.size(); ++i) m_playheadLines[i]->setVisible(shown[i]);
    };
    try {
        savePlotImage(*m_plot, m_plot->size(), path, tr("Session %1").arg(m_session.id));
    } catch (...) {
        restore();
        throw;
    }
    restore();
}

}  // namespace tactiscope::ui
