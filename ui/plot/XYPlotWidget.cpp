// XYPlotWidget: history of the two channels, strided curve, both axes fitted.
#include "ui/plot/XYPlotWidget.h"

#include "ui/common/NumberText.h"

#include <qcustomplot.h>

#include <QVBoxLayout>

#include <cmath>

namespace tactiscope::ui {
namespace {

constexpr int kRefresh_ms = 100;
constexpr double kMaxWindow_s = 60.0;

}  // namespace

XYPlotWidget::XYPlotWidget(QWidget* parent)
    : QWidget(parent),
      m_plot(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_plot);
    m_curve = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
    m_curve->setPen(QPen(QColor(0x0072B2), 1.5));
    m_slopeLabel = new QCPItemText(m_plot);
    m_slopeLabel->setObjectName(QStringLiteral("slopeLabel"));
    m_slopeLabel->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_slopeLabel->position->setCoords(0.03, 0.03);
    m_slopeLabel->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_slopeLabel->setPadding(QMargins(4, 2, 4, 2));
    m_slopeLabel->setBrush(QColor(255, 255, 255, 220));
    QFont bold = font();
    bold.setBold(true);
    m_slopeLabel->setFont(bold);
    // Opened as a dock, it must not be a sliver: a square of useful size.
    setMinimumSize(320, 280);
    m_plot->setPlottingHint(QCP::phFastPolylines, true);
    m_timer.setInterval(kRefresh_ms);
    connect(&m_timer, &QTimer::timeout, this, &XYPlotWidget::refresh);
}

XYPlotWidget::~XYPlotWidget() = default;

void XYPlotWidget::setSource(std::shared_ptr<const core::LiveBuffer> buffer, std::size_t x, std::size_t y,
                             const DisplayUnit& xUnit, const DisplayUnit& yUnit, double sampleRate_hz,
                             const QString& slopeName)
{
    clearSource();
    m_slopeName = slopeName;
    m_slopeUnit = xUnit.symbol == yUnit.symbol ? QString() : yUnit.symbol + QLatin1Char('/') + xUnit.symbol;
    if (!buffer || x >= buffer->channelCount() || y >= buffer->channelCount() || !(sampleRate_hz > 0.0)) return;
    m_buffer = std::move(buffer);
    m_x = x;
    m_y = y;
    m_xScale = xUnit.scale;
    m_yScale = yUnit.scale;
    m_rate_hz = sampleRate_hz;
    const auto capacity = static_cast<std::size_t>(std::ceil(kMaxWindow_s * sampleRate_hz)) + 1;
    m_xs = std::make_unique<core::RingBuffer<double>>(capacity);
    m_ys = std::make_unique<core::RingBuffer<double>>(capacity);
    m_plot->xAxis->setLabel(xUnit.axisTitle());
    m_plot->yAxis->setLabel(yUnit.axisTitle());
    m_timer.start();
}

void XYPlotWidget::clearSource()
{
    m_timer.stop();
    m_buffer.reset();
    m_cursor = {};
    m_xs.reset();
    m_ys.reset();
    m_curve->data()->clear();
    m_slope.reset();
    m_slopeLabel->setText(QString());
    m_plot->replot();
}

QString XYPlotWidget::slopeText() const
{
    if (!m_slope) return {};
    const QString value = significantText(*m_slope, 4);
    return m_slopeUnit.isEmpty() ? QStringLiteral("%1 = %2").arg(m_slopeName, value)
                                 : QStringLiteral("%1 = %2 %3").arg(m_slopeName, value, m_slopeUnit);
}

void XYPlotWidget::setWindowLength(double seconds)
{
    if (seconds > 0.0) m_window_s = std::min(seconds, kMaxWindow_s);
}

int XYPlotWidget::drawnPointCount() const
{
    return m_curve->dataCount();
}

std::pair<double, double> XYPlotWidget::xRange() const
{
    return {m_plot->xAxis->range().lower, m_plot->xAxis->range().upper};
}

std::pair<double, double> XYPlotWidget::yRange() const
{
    return {m_plot->yAxis->range().lower, m_plot->yAxis->range().upper};
}

void XYPlotWidget::refresh()
{
    if (!m_buffer || m_buffer->readNew(m_cursor, m_chunk) == 0) return;
    m_xs->push(std::span<const double>(m_chunk.values[m_x]));
    m_ys->push(std::span<const double>(m_chunk.values[m_y]));
    const auto wanted = static_cast<std::uint64_t>(std::ceil(m_window_s * m_rate_hz));
    const std::uint64_t end = m_xs->endIndex();
    const std::uint64_t first = std::max(m_xs->oldestIndex(), end > wanted ? end - wanted : 0);
    const std::uint64_t stride = std::max<std::uint64_t>(1, (end - first + kMaxPoints - 1) / kMaxPoints);
    QVector<double> t, xs, ys;
    for (std::uint64_t i = first; i < end; i += stride) {
        t.push_back(static_cast<double>(t.size()));
        xs.push_back(m_xs->at(i) * m_xScale);
        ys.push_back(m_ys->at(i) * m_yScale);
    }
    m_curve->setData(t, xs, ys, true);
    // Least squares through the origin, y = s·x, over the finite points.
    double xy = 0.0, xx = 0.0;
    std::size_t points = 0;
    for (qsizetype i = 0; i < xs.size(); ++i) {
        if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) continue;
        xy += xs[i] * ys[i];
        xx += xs[i] * xs[i];
        ++points;
    }
    m_slope = points >= 2 && xx > 0.0 ? std::optional(xy / xx) : std::nullopt;
    m_slopeLabel->setText(slopeText());
    bool foundX = false, foundY = false;  // false while every point is NaN
    const QCPRange x = m_curve->getKeyRange(foundX), y = m_curve->getValueRange(foundY);
    if (foundX && foundY) {
        m_plot->xAxis->setRange(x);
        m_plot->yAxis->setRange(y);
        m_plot->xAxis->scaleRange(1.1);
        m_plot->yAxis->scaleRange(1.1);
    }
    m_plot->replot();
}

}  // namespace tactiscope::ui
