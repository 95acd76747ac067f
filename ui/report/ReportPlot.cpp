// ReportPlot: lanes, bands and the session's records on QCustomPlot.
#include "ui/report/ReportPlot.h"
#include "ui/plot/AxisTicks.h"

#include "ui/common/DisplayUnits.h"
#include "ui/report/LaneAxis.h"
#include "ui/report/PlotImage.h"

#include <qcustomplot.h>

#include <algorithm>
#include <memory>

namespace tactiscope::ui {
namespace {

const QColor kTrace(31, 119, 180);
const QColor kDefectAThenB(217, 95, 2, 70);
const QColor kDefectBThenA(117, 112, 179, 70);
const QColor kReading(27, 158, 119, 50);
const QColor kMarker(90, 90, 90);
const QColor kGap(160, 160, 160, 90);
const QColor kAlarm(214, 39, 40, 45);  // a limit alarm, from its raise to its clear

// x in seconds on the lane's time axis, y as a fraction of the lane's height.
void placeInLane(QCPItemPosition* position, QCPAxisRect* rect, double time_s, double heightRatio)
{
    position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    position->setAxisRect(rect);
    position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    position->setCoords(time_s, heightRatio);
}

// A span at least `minimum_s` wide, centred on itself: a 10 ms defect on a
// minute-long axis would otherwise be narrower than a pixel, and invisible.
void shade(QCustomPlot& plot, QCPAxisRect* rect, double from_s, double to_s, const QColor& colour,
           double minimum_s = 0.0)
{
    if (to_s - from_s < minimum_s) {
        const double middle_s = 0.5 * (from_s + to_s);
        from_s = middle_s - 0.5 * minimum_s;
        to_s = middle_s + 0.5 * minimum_s;
    }
    auto* item = new QCPItemRect(&plot);
    item->setClipAxisRect(rect);
    placeInLane(item->topLeft, rect, from_s, 0.0);
    placeInLane(item->bottomRight, rect, to_s, 1.0);
    item->setPen(Qt::NoPen);
    item->setBrush(colour);
}

void mark(QCustomPlot& plot, QCPAxisRect* rect, double time_s)
{
    auto* line = new QCPItemStraightLine(&plot);
    line->setClipAxisRect(rect);
    placeInLane(line->point1, rect, time_s, 0.0);
    placeInLane(line->point2, rect, time_s, 1.0);
    line->setPen(QPen(kMarker, 1.0, Qt::DashLine));
}

// The lane's band: the max line filled down to the min line.
void addBand(QCustomPlot& plot, QCPAxisRect* rect, const core::report::ReportTrace& trace, const DisplayUnit& unit)
{
    QCPGraph* low = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    QCPGraph* high = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    const double rate_hz = trace.channel.sampleRate_hz;
    for (const auto& p : trace.points) {
        const double t_s = (static_cast<double>(p.firstIndex) + 0.5 * static_cast<double>(p.count)) / rate_hz;
        // NaN (a stretch inside a gap) breaks the line, as it should.
        low->addData(t_s, p.min * unit.scale);
        high->addData(t_s, p.max * unit.scale);
    }
    low->setPen(QPen(kTrace, 1.0));
    high->setPen(QPen(kTrace, 1.0));
    high->setBrush(QColor(kTrace.red(), kTrace.green(), kTrace.blue(), 110));
    high->setChannelFillGraph(low);
    bool found = false;
    QCPRange shown = low->getValueRange(found);
    if (found) {
        bool foundHigh = false;
        shown.expand(high->getValueRange(foundHigh));
    }
    fitLaneRange(*rect->axis(QCPAxis::atLeft), unit, found ? std::optional(shown) : std::nullopt, trace.threshold);
}

// Builds the plot `width` pixels wide; the caller renders it.
std::unique_ptr<QCustomPlot> buildPlot(const core::report::ReportData& data, int width)
{
    auto plot = std::make_unique<QCustomPlot>();
    plot->plotLayout()->clear();
    auto* margins = new QCPMarginGroup(plot.get());
    const double rate_hz = data.session.sampleRate_hz;
    // Defects at least 2 px wide in a lane, which is the plot less its
    // axis margin (under 100 px).
    const double minimumEvent_s = 2.0 * (data.to_s - data.from_s) / std::max(1, width - 100);
    for (std::size_t lane = 0; lane < data.traces.size(); ++lane) {
        const auto& trace = data.traces[lane];
        auto* rect = new QCPAxisRect(plot.get());
        plot->plotLayout()->addElement(static_cast<int>(lane), 0, rect);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        const DisplayUnit unit = laneUnit(trace.channel.descriptor, data.session.metadata.mode);
        setUpLaneAxis(*rect, unit, trace.threshold);
        QCPAxis* time = rect->axis(QCPAxis::atBottom);
        time->setRange(data.from_s, data.to_s);
        // Only the bottom lane names the shared time axis.
        time->setTickLabels(lane + 1 == data.traces.size());
        if (lane + 1 == data.traces.size()) time->setLabel(QObject::tr("Time (s)"));
        for (const auto& gap : data.gaps)
            shade(*plot, rect, static_cast<double>(gap.firstIndex) / rate_hz,
                  static_cast<double>(gap.firstIndex + gap.count) / rate_hz, kGap);
        for (const auto& event : data.events) {
            if (event.kind == core::EventKind::Defect)
                shade(*plot, rect, event.start_s, event.end_s, event.direction > 0 ? kDefectAThenB : kDefectBThenA,
                      minimumEvent_s);
            else if (event.kind == core::EventKind::Marker || event.kind == core::EventKind::Trigger)
                mark(*plot, rect, event.start_s);
            else if (event.kind == core::EventKind::Alarm && event.end_s > event.start_s)
                shade(*plot, rect, event.start_s, event.end_s, kAlarm, minimumEvent_s);
        }
        for (const auto& reading : data.readings) shade(*plot, rect, reading.start_s, reading.end_s, kReading);
        addBand(*plot, rect, trace, unit);
    }
    return plot;
}

}  // namespace

QImage renderReportPlot(const core::report::ReportData& data, QSize size, double scale)
{
    const auto plot = buildPlot(data, size.width());
    // Laid out at the image's size first, so each lane knows its height
    // and gets ticks with two labels at least, none overlapping.
    plot->setGeometry(QRect(QPoint(), size));
    plot->replot();
    const double line = QFontMetrics(plot->font()).height();
    for (QCPAxisRect* rect : plot->axisRects()) fitTickCount(*rect->axis(QCPAxis::atLeft), rect->height(), line, 3);
    return plot->toPixmap(size.width(), size.height(), scale).toImage();
}

void saveReportPlot(const core::report::ReportData& data, QSize size, const QString& path)
{
    const auto plot = buildPlot(data, size.width());
    savePlotImage(*plot, size, path, QObject::tr("Session %1").arg(data.session.id));
}

}  // namespace tactiscope::ui
