// LaneAxis: label, ticker, threshold line and range of one lane.
#include "ui/report/LaneAxis.h"

#include "ui/plot/AxisTicks.h"

#include <qcustomplot.h>

#include <cmath>

namespace tactiscope::ui {
namespace {

const QColor kThreshold{QRgb(kThresholdRgb)};

}  // namespace

void setUpLaneAxis(QCPAxisRect& lane, const DisplayUnit& unit, std::optional<double> threshold_si)
{
    QCPAxis* values = lane.axis(QCPAxis::atLeft);
    values->setLabel(laneLabel(unit));
    useEvenDecimals(*values);
    values->ticker()->setTickCount(3);
    if (!unit.levels.empty()) {
        QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
        for (const auto& [value, name] : unit.levels) ticker->addTick(value, name);
        values->setTicker(ticker);
    }
    if (!threshold_si) return;
    auto* line = new QCPItemStraightLine(values->parentPlot());
    line->setClipAxisRect(&lane);
    for (QCPItemPosition* point : {line->point1, line->point2}) point->setAxes(lane.axis(QCPAxis::atBottom), values);
    line->point1->setCoords(0.0, *threshold_si * unit.scale);
    line->point2->setCoords(1.0, *threshold_si * unit.scale);
    line->setPen(QPen(kThreshold, 1.0, Qt::DashLine));
    line->setSelectable(false);
}

void fitLaneRange(QCPAxis& values, const DisplayUnit& unit, std::optional<QCPRange> shown,
                  std::optional<double> threshold_si)
{
    if (!unit.levels.empty()) {  // every level in view, whatever is shown
        values.setRange(unit.levels.front().first - 0.4, unit.levels.back().first + 0.4);
        return;
    }
    if (!shown) return;
    QCPRange range = *shown;
    if (threshold_si) range.expand(*threshold_si * unit.scale);
    // A flat trace gets a visible band around it, in display units.
    const double margin =
        range.size() > 0.0 ? 0.08 * range.size() : (range.lower != 0.0 ? 0.1 * std::abs(range.lower) : 1.0);
    values.setRange(range.lower - margin, range.upper + margin);
}

}  // namespace tactiscope::ui
