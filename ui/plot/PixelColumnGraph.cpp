// PixelColumnGraph: a polyline rasterised into per-column pixel runs.
#include "ui/plot/PixelColumnGraph.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::ui {

PixelColumnGraph::PixelColumnGraph(QCPAxis* keyAxis, QCPAxis* valueAxis)
    : QCPGraph(keyAxis, valueAxis)
{
}

void PixelColumnGraph::drawLinePlot(QCPPainter* painter, const QVector<QPointF>& lines) const
{
    applyDefaultAntialiasingHint(painter);
    const QPen pen = painter->pen();
    const QTransform toDevice = painter->deviceTransform();
    auto* image = dynamic_cast<QImage*>(painter->device());
    const QCPAxis* key = keyAxis();
    const bool thin = pen.isCosmetic() || pen.widthF() <= 1.0;
    if (!image || image->depth() != 32 || image->hasAlphaChannel() || toDevice.type() > QTransform::TxScale || !key ||
        key->orientation() != Qt::Horizontal || pen.style() != Qt::SolidLine || pen.color().alpha() != 255 || !thin ||
        painter->antialiasing()) {
        QCPGraph::drawLinePlot(painter, lines);
        return;
    }
    // The pixels the painter may touch: its clip (the axis rect) on the image.
    QRect area = image->rect();
    if (painter->hasClipping()) area &= toDevice.mapRect(painter->clipBoundingRect()).toAlignedRect();
    if (area.isEmpty()) return;
    const int left = area.left();
    const auto columns = static_cast<std::size_t>(area.width());
    constexpr float kNone = std::numeric_limits<float>::infinity();
    m_top.assign(columns, kNone);
    m_bottom.assign(columns, -kNone);
    // Rows outside the area are held just past it and cut when written: a
    // value of 1e300 must not overflow a pixel coordinate.
    const double rowLow = area.top() - 1.0;
    const double rowHigh = area.bottom() + 1.0;
    const double areaEnd = static_cast<double>(left) + static_cast<double>(columns);
    const auto widen = [&](double x, double y) {
        if (!(x >= left && x < areaEnd)) return;  // outside (or NaN): no pixel, and no cast of a huge x
        const auto column = static_cast<std::size_t>(x - left);
        const auto row = static_cast<float>(std::clamp(y, rowLow, rowHigh));
        auto& top = m_top[column];
        auto& bottom = m_bottom[column];
        top = std::min(top, row);
        bottom = std::max(bottom, row);
    };
    // A segment widens every column it crosses by its own height there:
    // both ends of the part of it above that column.
    const auto segment = [&](QPointF a, QPointF b) {
        if (a.x() > b.x()) std::swap(a, b);
        const double firstColumn = std::floor(a.x());
        const double lastColumn = std::floor(b.x());
        if (firstColumn == lastColumn) {
            widen(a.x(), a.y());
            widen(b.x(), b.y());
            return;
        }
        const double slope = (b.y() - a.y()) / (b.x() - a.x());
        const double from = std::max(firstColumn, left - 1.0);
        const double to = std::min(lastColumn, areaEnd);
        for (double column = from; column <= to; ++column) {
            const double x0 = std::max(a.x(), column);
            const double x1 = std::min(b.x(), column + 1.0);
            widen(column, a.y() + slope * (x0 - a.x()));
            widen(column, a.y() + slope * (x1 - a.x()));
        }
    };
    // A point is in the column it falls in and the row whose centre is
    // nearest, as the raster engine places an aliased line's (the test
    // compares them): half a row down, then floored as the columns are.
    const auto onDevice = [&toDevice](const QPointF& p) { return toDevice.map(p) + QPointF(0.0, 0.5); };
    const auto finite = [](const QPointF& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); };
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QPointF point = onDevice(lines[i]);
        if (!finite(point)) continue;  // a gap: the line is broken there
        if (i + 1 < lines.size() && finite(lines[i + 1]))
            segment(point, onDevice(lines[i + 1]));
        else
            widen(point.x(), point.y());
    }
    const QRgb colour = pen.color().rgba();
    const qsizetype stride = image->bytesPerLine();
    uchar* const bits = image->bits();
    for (std::size_t c = 0; c < columns; ++c) {
        if (m_top[c] > m_bottom[c]) continue;
        const int top = std::max(static_cast<int>(std::floor(m_top[c])), area.top());
        const int bottom = std::min(static_cast<int>(std::floor(m_bottom[c])), area.bottom());
        const auto x = static_cast<qsizetype>(left) + static_cast<qsizetype>(c);
        for (int y = top; y <= bottom; ++y) reinterpret_cast<QRgb*>(bits + y * stride)[x] = colour;
    }
}

}  // namespace tactiscope::ui
