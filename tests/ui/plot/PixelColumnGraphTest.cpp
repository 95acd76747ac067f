// PixelColumnGraph on OpaqueCustomPlot against the raster engine's own
// polyline of the same points (QCPGraph): in every pixel column the trace
// covers the same rows within a pixel, for dense min/max traces, sparse
// diagonals, steps and gaps, at 100 % and 200 % scale; values far off the
// axis are cut at its edge. The polyline is Qt's rasteriser, not this code.
#include "ui/plot/PixelColumnGraph.h"
#include "ui/plot/OpaqueCustomPlot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

using namespace tactiscope;

namespace {

constexpr QRgb kTrace = 0xff0072b2;

// Per pixel column of `image` inside `area`, the first and last row of the
// trace's colour; none where the column has none.
struct Run {
    int top = 0;
    int bottom = 0;
};
std::vector<std::optional<Run>> runsIn(const QImage& image, const QRect& area)
{
    std::vector<std::optional<Run>> runs(static_cast<std::size_t>(area.width()));
    for (int x = area.left(); x <= area.right(); ++x) {
        for (int y = area.top(); y <= area.bottom(); ++y) {
            if (image.pixel(x, y) != kTrace) continue;
            auto& run = runs[static_cast<std::size_t>(x - area.left())];
            if (!run) run = Run{y, y};
            run->bottom = y;
        }
    }
    return runs;
}

// The plot as the live view has it, 600 × 300, one trace of `keys` and
// `values` on axes 0..10 × -1..1, drawn by a PixelColumnGraph or by
// QCustomPlot's own graph; the widget's pixels (device pixels at `scale`)
// and the axis rect in them.
struct Drawn {
    QImage image;
    QRect area;
};
Drawn draw(bool columns, const QVector<double>& keys, const QVector<double>& values, double scale = 1.0)
{
    ui::OpaqueCustomPlot plot;
    plot.resize(600, 300);
    plot.setBufferDevicePixelRatio(scale);
    plot.setNotAntialiasedElements(QCP::aePlottables);
    for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {  // nothing but the trace inside the axis rect
        axis->grid()->setVisible(false);
        axis->setTicks(false);
    }
    QCPGraph* graph = columns ? new ui::PixelColumnGraph(plot.xAxis, plot.yAxis) : plot.addGraph();
    graph->setPen(QPen(QColor(kTrace), 1.0));
    graph->setAdaptiveSampling(false);
    graph->setData(keys, values, true);
    plot.xAxis->setRange(0.0, 10.0);
    plot.yAxis->setRange(-1.0, 1.0);
    plot.replot();
    QImage image(QSize(600, 300) * scale, QImage::Format_RGB32);
    image.setDevicePixelRatio(scale);
    image.fill(Qt::white);
    plot.render(&image);
    const QRect rect = plot.axisRect()->rect();
    // Inside the rect, clear of its frame: the axes' lines are not the trace.
    const QRect area(QPoint(static_cast<int>(std::ceil(rect.left() * scale)) + 1,
                            static_cast<int>(std::ceil(rect.top() * scale)) + 1),
                     QPoint(static_cast<int>(std::floor(rect.right() * scale)) - 1,
                            static_cast<int>(std::floor(rect.bottom() * scale)) - 1));
    return {image, area};
}

// Both drawings cover the same rows in every column, within `tolerance`
// pixels at each end (the two round a steep segment's ends apart: by two
// rows at the turns of a dense trace); a column the one leaves empty the other leaves empty
// too, but for one column either side of the ends of a line (where the
// two rasterisers round its end apart).
void expectSameTrace(const QVector<double>& keys, const QVector<double>& values, double scale = 1.0, int tolerance = 2)
{
    const Drawn ours = draw(true, keys, values, scale);
    const Drawn qts = draw(false, keys, values, scale);
    ASSERT_EQ(ours.area, qts.area);
    const auto oursRuns = runsIn(ours.image, ours.area);
    const auto qtsRuns = runsIn(qts.image, qts.area);
    int compared = 0;
    for (std::size_t c = 0; c < oursRuns.size(); ++c) {
        const auto& a = oursRuns[c];
        const auto& b = qtsRuns[c];
        const auto near = [&](std::size_t other) {
            return other < oursRuns.size() && (oursRuns[other].has_value() != qtsRuns[other].has_value());
        };
        if (a.has_value() != b.has_value()) {
            // Only at a line's end, where the next column over already differs or is empty.
            const bool atEnd = (c > 0 && !(oursRuns[c - 1] && qtsRuns[c - 1])) ||
                               (c + 1 < oursRuns.size() && !(oursRuns[c + 1] && qtsRuns[c + 1]));
            EXPECT_TRUE(atEnd || near(c)) << "column " << c << (a ? " drawn here only" : " drawn by Qt only");
            continue;
        }
        if (!a) continue;
        ++compared;
        EXPECT_NEAR(a->top, b->top, tolerance) << "column " << c;
        EXPECT_NEAR(a->bottom, b->bottom, tolerance) << "column " << c;
    }
    EXPECT_GT(compared, 0);
}

}  // namespace

TEST(PixelColumnGraph, ADenseMinMaxTraceCoversTheRowsQtsPolylineDoes)
{
    // Four points per pixel column, a sine with a fast wobble, as the
    // decimation hands the live view a 10 kHz channel.
    QVector<double> keys, values;
    for (int i = 0; i <= 4000; ++i) {
        const double t = i * 10.0 / 4000;
        keys.append(t);
        values.append(0.7 * std::sin(2.0 * std::numbers::pi * 0.4 * t) + (i % 2 == 0 ? -0.05 : 0.05));
    }
    expectSameTrace(keys, values);
}

TEST(PixelColumnGraph, ASparseTraceIsDrawnAsItsSlopingLines)
{
    // Ten points across 600 pixels: each segment crosses some sixty columns.
    QVector<double> keys{0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0};
    QVector<double> values{-0.9, 0.8, -0.2, 0.1, 0.95, -0.95, 0.0, 0.3, -0.6, 0.5, 0.2};
    expectSameTrace(keys, values);
}

TEST(PixelColumnGraph, AFlatLineIsOneRowAndAStepIsOneColumn)
{
    QVector<double> keys{0.0, 5.0, 5.0, 10.0};
    QVector<double> values{-0.5, -0.5, 0.5, 0.5};
    expectSameTrace(keys, values);
    const Drawn ours = draw(true, keys, values);
    const auto runs = runsIn(ours.image, ours.area);
    int tall = 0;
    for (const auto& run : runs) {
        ASSERT_TRUE(run.has_value());
        if (run->bottom > run->top)
            ++tall;
        else
            EXPECT_EQ(run->top, run->bottom);
    }
    EXPECT_EQ(tall, 1);  // the step, in the one column at t = 5 s
}

TEST(PixelColumnGraph, AGapLeavesItsColumnsEmpty)
{
    QVector<double> keys, values;
    for (int i = 0; i <= 1000; ++i) {
        const double t = i * 0.01;
        keys.append(t);
        // From 4 s to 6 s, no value: the line is broken there.
        values.append(t > 4.0 && t < 6.0 ? std::numeric_limits<double>::quiet_NaN() : 0.5 * std::sin(t));
    }
    expectSameTrace(keys, values);
    const Drawn ours = draw(true, keys, values);
    const auto runs = runsIn(ours.image, ours.area);
    const double columnsPerSecond = static_cast<double>(runs.size()) / 10.0;
    for (auto c = static_cast<std::size_t>(4.2 * columnsPerSecond);
         c < static_cast<std::size_t>(5.8 * columnsPerSecond); ++c)
        EXPECT_FALSE(runs[c].has_value()) << "column " << c;
}

TEST(PixelColumnGraph, ValuesFarOffTheAxisAreCutAtItsEdge)
{
    // Off the axis by a few heights: the lines run out of the rect as Qt's do.
    const QVector<double> keys{0.0, 2.0, 4.0, 6.0, 8.0, 10.0};
    expectSameTrace(keys, {0.0, 5.0, 0.0, -7.0, 0.5, 0.0});
    // Off by more than a pixel coordinate holds: no crash, nothing drawn
    // outside the axis rect, and the trace still drawn where it is inside.
    const double inf = std::numeric_limits<double>::infinity();
    const Drawn ours = draw(true, keys, {0.0, 1e300, 0.0, -1e300, inf, 0.0});
    const QRect inside = ours.area.adjusted(-2, -2, 2, 2);  // the axis rect, its frame and QCustomPlot's clip
    int drawn = 0;
    for (int y = 0; y < ours.image.height(); ++y)
        for (int x = 0; x < ours.image.width(); ++x) {
            if (ours.image.pixel(x, y) != kTrace) continue;
            EXPECT_TRUE(inside.contains(x, y)) << x << ", " << y;
            ++drawn;
        }
    EXPECT_GT(drawn, 0);
}

TEST(PixelColumnGraph, AtTwiceTheScaleItDrawsInDevicePixels)
{
    QVector<double> keys, values;
    for (int i = 0; i <= 3000; ++i) {
        const double t = i * 10.0 / 3000;
        keys.append(t);
        values.append(0.8 * std::sin(2.0 * std::numbers::pi * 0.3 * t));
    }
    expectSameTrace(keys, values, 2.0);
}
