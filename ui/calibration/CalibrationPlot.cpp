// CalibrationPlot: two stacked axis rects, points, fit line, residuals.
#include "ui/calibration/CalibrationPlot.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace tactiscope::ui {
namespace {

enum Graph { Loading, Unloading, Line, LoadingResidual, UnloadingResidual };

void addPointGraph(QCustomPlot* plot, QCPAxisRect* rect, const QColor& colour, QCPScatterStyle::ScatterShape shape,
                   const QString& name)
{
    QCPGraph* graph = plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(QCPScatterStyle(shape, colour, colour, 7));
    graph->setName(name);
}

}  // namespace

CalibrationPlot::CalibrationPlot(QWidget* parent)
    : QWidget(parent),
      m_plot(new QCustomPlot(this))
{
    setObjectName(QStringLiteral("calibrationPlot"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    setMinimumSize(360, 280);

    QCPAxisRect* main = m_plot->axisRect();
    auto* residualRect = new QCPAxisRect(m_plot);
    m_plot->plotLayout()->addElement(1, 0, residualRect);
    m_plot->plotLayout()->setRowStretchFactor(1, 0.45);
    // Both rects share their left margin, so the x axes line up.
    auto* margins = new QCPMarginGroup(m_plot);
    main->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    residualRect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    connect(main->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
            residualRect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));

    const QColor loading(0x1f, 0x77, 0xb4), unloading(0xd6, 0x27, 0x28);
    addPointGraph(m_plot, main, loading, QCPScatterStyle::ssDisc, tr("loading"));
    addPointGraph(m_plot, main, unloading, QCPScatterStyle::ssCircle, tr("unloading"));
    QCPGraph* line = m_plot->addGraph(main->axis(QCPAxis::atBottom), main->axis(QCPAxis::atLeft));
    line->setPen(QPen(QColor(0x55, 0x55, 0x55), 1.2, Qt::DashLine));
    line->setName(tr("fit"));
    addPointGraph(m_plot, residualRect, loading, QCPScatterStyle::ssDisc, {});
    addPointGraph(m_plot, residualRect, unloading, QCPScatterStyle::ssCircle, {});

    main->insetLayout()->addElement(m_plot->legend, Qt::AlignTop | Qt::AlignLeft);
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(QFont(font().family(), 8));
    m_plot->legend->removeItem(m_plot->legend->itemCount() - 1);  // the residual graphs need no entry
    m_plot->legend->removeItem(m_plot->legend->itemCount() - 1);
    // A zero line for the residuals.
    auto* zero = new QCPItemStraightLine(m_plot);
    zero->setClipAxisRect(residualRect);
    zero->point1->setAxes(residualRect->axis(QCPAxis::atBottom), residualRect->axis(QCPAxis::atLeft));
    zero->point2->setAxes(residualRect->axis(QCPAxis::atBottom), residualRect->axis(QCPAxis::atLeft));
    zero->point1->setCoords(0, 0);
    zero->point2->setCoords(1, 0);
    zero->setPen(QPen(Qt::gray, 1));
}

void CalibrationPlot::setTitles(const QString& x, const QString& y, const QString& residual)
{
    QCPAxisRect* main = m_plot->axisRect(0);
    QCPAxisRect* residualRect = m_plot->axisRect(1);
    main->axis(QCPAxis::atLeft)->setLabel(y);
    residualRect->axis(QCPAxis::atLeft)->setLabel(residual);
    residualRect->axis(QCPAxis::atBottom)->setLabel(x);
}

void CalibrationPlot::setSeriesNames(const QString& loading, const QString& unloading)
{
    m_plot->graph(Loading)->setName(loading);
    m_plot->graph(Unloading)->setName(unloading);
    m_plot->replot();
}

void CalibrationPlot::setData(const std::vector<CalibrationPoint>& points,
                              std::optional<std::pair<double, double>> slopeIntercept)
{
    QVector<double> x[2], y[2], r[2];
    m_residuals.clear();
    double xMax = 0.0;
    for (const CalibrationPoint& p : points) {
        const int set = p.loading ? 0 : 1;
        x[set].push_back(p.x);
        y[set].push_back(p.y);
        xMax = std::max(xMax, p.x);
        if (slopeIntercept) {
            m_residuals.push_back(p.y - (slopeIntercept->second + slopeIntercept->first * p.x));
            r[set].push_back(m_residuals.back());
        }
    }
    m_plot->graph(Loading)->setData(x[0], y[0], true);
    m_plot->graph(Unloading)->setData(x[1], y[1], true);
    m_plot->graph(LoadingResidual)->setData(x[0], r[0], true);
    m_plot->graph(UnloadingResidual)->setData(x[1], r[1], true);
    if (slopeIntercept) {
        const auto [slope, intercept] = *slopeIntercept;
        m_plot->graph(Line)->setData(QVector<double>{0.0, xMax}, QVector<double>{intercept, intercept + slope * xMax});
    } else {
        m_plot->graph(Line)->data()->clear();
    }
    m_plot->graph(Unloading)->removeFromLegend();
    if (!y[1].isEmpty()) m_plot->graph(Unloading)->addToLegend();

    QCPAxisRect* main = m_plot->axisRect(0);
    QCPAxisRect* residualRect = m_plot->axisRect(1);
    m_plot->rescaleAxes();
    // Some air around the points; a residual axis symmetric about zero.
    const QCPRange xr = main->axis(QCPAxis::atBottom)->range();
    main->axis(QCPAxis::atBottom)->setRange(xr.lower - 0.05 * xr.size(), xr.upper + 0.05 * xr.size());
    main->axis(QCPAxis::atLeft)->scaleRange(1.1);
    double largest = 0.0;
    for (double v : m_residuals) largest = std::max(largest, std::abs(v));
    residualRect->axis(QCPAxis::atLeft)->setRange(-1.3 * largest - 1e-300, 1.3 * largest + 1e-300);
    m_plot->replot();
}

}  // namespace tactiscope::ui
