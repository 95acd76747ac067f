// PixelColumnGraph is a QCPGraph that draws its line by setting, in each
// pixel column of its axis rect, the run of pixels the line passes
// through, written straight into the plot's image buffer.
//
// Why: a live trace has two points or more per pixel column (min/max
// decimation), so its polyline is thousands of short vertical segments,
// and the raster engine blends each of their pixels through a span
// function of its own: at 16 × 10 kHz most of the GUI thread (perf). The
// runs are those the polyline covers (a segment crossing several columns,
// as when zoomed in, gives each the part of it above that column), so the
// trace looks as before, one pixel wide, and costs a store per pixel.
// Only for what the live view draws: a horizontal key axis, a thin opaque
// unsmoothed solid pen, an OpaqueCustomPlot's image under a scaling and
// translating painter; anything else QCPGraph draws as before.
#pragma once

#include <qcustomplot.h>

#include <vector>

namespace tactiscope::ui {

class PixelColumnGraph : public QCPGraph {
    Q_OBJECT

public:
    PixelColumnGraph(QCPAxis* keyAxis, QCPAxis* valueAxis);

protected:
    void drawLinePlot(QCPPainter* painter, const QVector<QPointF>& lines) const override;

private:
    // Per pixel column of the image, the highest and lowest row the line
    // passes through; kept between frames so a frame allocates nothing.
    mutable std::vector<float> m_top;
    mutable std::vector<float> m_bottom;
};

}  // namespace tactiscope::ui
