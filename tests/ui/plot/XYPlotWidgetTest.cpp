// XYPlotWidget on real widgets (offscreen): the last seconds of one channel
// against another, strided to at most kMaxPoints, axes fitted around them,
// NaN (no value) left out of the fit.
#include "ui/plot/XYPlotWidget.h"

#include "core/SampleBlock.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::testing::waitFor;

TEST(XYPlotWidget, DrawsTheLastSecondsOfOneChannelAgainstAnother)
{
    // 20 s at 1 kHz of x = t, y = 3t, with NaN for y in the first second.
    auto buffer = std::make_shared<core::LiveBuffer>(2, 30000);
    for (std::uint64_t first = 0; first < 20000; first += 100) {
        core::SampleBlock block(2, 100, static_cast<double>(first) * 1e-3, 1e-3, first);
        for (std::size_t i = 0; i < 100; ++i) {
            const double t = block.timeAt_s(i);
            block.channel(0)[i] = t;
            block.channel(1)[i] = t < 1.0 ? std::nan("") : 3.0 * t;
        }
        buffer->consume(block);
    }
    ui::XYPlotWidget plot;
    plot.resize(500, 400);
    plot.show();
    plot.setSource(buffer, 0, 1, {1.0, "s", "x"}, {1.0, "s", "y"}, 1000.0);
    ASSERT_TRUE(waitFor([&] { return plot.drawnPointCount() > 0; }, 2000));
    // 10 s window = 10 000 samples, strided to at most kMaxPoints .
    EXPECT_LE(plot.drawnPointCount(), static_cast<int>(ui::XYPlotWidget::kMaxPoints));
    EXPECT_GE(plot.drawnPointCount(), static_cast<int>(ui::XYPlotWidget::kMaxPoints) / 2);
    // The window is t in [10, 20): x from 10 to 20, y from 30 to 60, padded 10 %.
    const auto [x0, x1] = plot.xRange();
    const auto [y0, y1] = plot.yRange();
    EXPECT_NEAR(x0, 15.0 - 5.5, 0.01);
    EXPECT_NEAR(x1, 15.0 + 5.5, 0.01);
    EXPECT_NEAR(y0, 45.0 - 16.5, 0.01);
    EXPECT_NEAR(y1, 45.0 + 16.5, 0.01);
    // y = 3x through the origin: the slope, shown with its unit (s/s: none).
    ASSERT_TRUE(plot.slope().has_value());
    EXPECT_NEAR(*plot.slope(), 3.0, 1e-9);
    EXPECT_EQ(plot.slopeText(), QStringLiteral("slope = 3.000"));
    EXPECT_FALSE(tactiscope::testing::saveScreenshot(plot, QStringLiteral("xy-plot")).isEmpty());
}
