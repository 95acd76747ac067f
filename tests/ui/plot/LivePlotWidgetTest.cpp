// LivePlotWidget on real widgets (offscreen): decimation to the screen,
// one lane per unit, the display's own overrun accounting, pause with
// scroll-back while samples keep coming, and a held value scale.
#include "ui/plot/LivePlotWidget.h"

#include "core/SampleBlock.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"

#include <qcustomplot.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace tactiscope;
using tactiscope::testing::saveScreenshot;
using tactiscope::testing::waitFor;

namespace {

// A 1 Hz strain sine (±20 µε) and a slowly rising capacitance around
// 50 pF, at 500 Hz, from `from_s` to `to_s`, appended to `buffer` in
// 10-sample blocks.
void fill(core::LiveBuffer& buffer, double from_s, double to_s)
{
    const double dt = 0.002;
    const auto total = static_cast<std::uint64_t>(std::llround(to_s / dt));
    for (auto first = static_cast<std::uint64_t>(std::llround(from_s / dt)); first < total; first += 10) {
        core::SampleBlock block(2, 10, static_cast<double>(first) * dt, dt, first);
        for (std::size_t i = 0; i < 10; ++i) {
            const double t = block.timeAt_s(i);
            block.channel(0)[i] = 20e-6 * std::sin(2.0 * std::numbers::pi * t);
            block.channel(1)[i] = 50e-12 + 0.1e-12 * t;
        }
        buffer.consume(block);
    }
}

const std::vector<core::ChannelDescriptor> kChannels{{"gauge", "", core::ChannelKind::Strain},
                                                     {"beam", "F", core::ChannelKind::Capacitance}};

}  // namespace

TEST(LivePlotWidget, DrawsAtMostTwoPointsPerPixelColumnInOneLanePerUnit)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*buffer, 0.0, 20.0);  // 10 000 samples; the 10 s window holds 5 000
    ui::LivePlotWidget plot;
    plot.resize(900, 600);
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);

    ASSERT_TRUE(waitFor([&] { return plot.drawnPointCount(0) > 0; }, 2000));
    EXPECT_EQ(plot.laneCount(), 2u);
    EXPECT_EQ(plot.samplesReceived(), 10000u);
    EXPECT_EQ(plot.samplesOverrun(), 0u);
    // The plot area is narrower than the widget, so 2 × 900 + 2 bounds it.
    EXPECT_LE(plot.drawnPointCount(0), 2 * 900 + 2);
    EXPECT_LT(plot.drawnPointCount(0), 5000);
    EXPECT_GT(plot.drawnPointCount(1), 0);
    EXPECT_FALSE(saveScreenshot(plot, QStringLiteral("live-plot-two-lanes")).isEmpty());
}

TEST(LivePlotWidget, LostSamplesAreDrawnAsAGapNotJoined)
{
    // 0–4 s, then the device loses 2 s (as after a reconnect), then 6–9 s.
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*buffer, 0.0, 4.0);
    fill(*buffer, 6.0, 9.0);
    ui::LivePlotWidget plot;
    plot.resize(900, 600);
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 3500u && plot.drawnPointCount(0) > 0; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    ASSERT_EQ(plot.gapsShown().size(), 1u);
    EXPECT_NEAR(plot.gapsShown()[0].from_s, 3.998, 0.02);
    EXPECT_NEAR(plot.gapsShown()[0].to_s, 6.0, 0.02);
    EXPECT_FALSE(saveScreenshot(plot, QStringLiteral("live-plot-gap")).isEmpty());

    // The same 9 s without the loss: no gap.
    auto whole = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*whole, 0.0, 9.0);
    plot.setSource(whole, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 4500u && plot.drawnPointCount(0) > 0; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    EXPECT_TRUE(plot.gapsShown().empty());
}

// Issue 52: a probe away longer than the window came back with no grey
// band until the view was panned.
TEST(LivePlotWidget, AGapLongerThanTheWindowIsShownUpToItsLeftEdge)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*buffer, 0.0, 4.0);
    fill(*buffer, 30.0, 33.0);  // 26 s away; the window is 10 s
    ui::LivePlotWidget plot;
    plot.resize(900, 600);
    plot.show();
    plot.setWindowLength(10.0);
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 3500u && plot.drawnPointCount(0) > 0; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    ASSERT_EQ(plot.gapsShown().size(), 1u);
    EXPECT_NEAR(plot.gapsShown()[0].from_s, 33.0 - 10.0, 0.02);
    EXPECT_NEAR(plot.gapsShown()[0].to_s, 30.0, 0.02);
}

TEST(LivePlotWidget, CountsSamplesItMissedWhenTheBufferOverran)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 100);
    fill(*buffer, 0.0, 2.0);  // 1000 samples into a 100-sample buffer
    ui::LivePlotWidget plot;
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() > 0; }, 2000));
    EXPECT_EQ(plot.samplesReceived(), 1000u);
    EXPECT_EQ(plot.samplesOverrun(), 900u);
}

TEST(LivePlotWidget, ClearingTheSourceRemovesTheTraces)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 2000);
    fill(*buffer, 0.0, 1.0);
    ui::LivePlotWidget plot;
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.drawnPointCount(0) > 0; }, 2000));
    plot.clearSource();
    EXPECT_EQ(plot.drawnPointCount(0), 0);
    EXPECT_EQ(plot.laneCount(), 0u);
    EXPECT_EQ(plot.samplesReceived(), 0u);
}

TEST(LivePlotWidget, PausedItKeepsTakingSamplesAndScrollsBackThroughThem)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*buffer, 0.0, 20.0);
    ui::LivePlotWidget plot;
    plot.resize(900, 600);
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 10000u && plot.drawnPointCount(0) > 0; }, 2000));
    const auto live = plot.visibleTimeRange();
    EXPECT_NEAR(live.second, 19.998, 1e-9);  // the newest sample at the right edge
    EXPECT_NEAR(live.second - live.first, 10.0, 1e-9);

    // Nothing new, nothing drawn: frames only follow data.
    const auto frames = plot.framesDrawn();
    tactiscope::testing::runEventLoopFor(200);
    EXPECT_EQ(plot.framesDrawn(), frames);

    plot.setPaused(true);
    fill(*buffer, 20.0, 30.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 15000u; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    EXPECT_EQ(plot.visibleTimeRange(), live);  // frozen while samples arrive

    plot.scrollTo(2.0);  // back before the pause
    ASSERT_TRUE(waitFor([&] { return plot.visibleTimeRange().first == 2.0; }, 1000));
    tactiscope::testing::runEventLoopFor(100);
    EXPECT_GT(plot.drawnPointCount(0), 100);
    EXPECT_FALSE(saveScreenshot(plot, QStringLiteral("live-plot-paused")).isEmpty());

    plot.setPaused(false);  // back to the newest samples, including those taken while paused
    EXPECT_TRUE(waitFor([&] { return std::abs(plot.visibleTimeRange().second - 29.998) < 1e-9; }, 1000));
    EXPECT_EQ(plot.samplesOverrun(), 0u);
}

TEST(LivePlotWidget, AHeldScaleStopsAutoscaling)
{
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    fill(*buffer, 0.0, 10.0);
    ui::LivePlotWidget plot;
    plot.show();
    plot.setSource(buffer, kChannels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 5000u; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    plot.setScaleHeld(true);
    const auto held = plot.valueRange(1);  // the capacitance, rising 0.1 pF/s
    fill(*buffer, 10.0, 40.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 20000u; }, 2000));
    tactiscope::testing::runEventLoopFor(100);
    EXPECT_EQ(plot.valueRange(1), held);

    plot.setScaleHeld(false);
    fill(*buffer, 40.0, 40.1);
    EXPECT_TRUE(waitFor([&] { return plot.valueRange(1).second > held.second + 2.0; }, 1000));
}

TEST(LivePlotWidget, NoTraceRunsUnderTheLegend)
{
    // Two strain traces share a lane, so it has a legend in its top left;
    // both are at their highest in the first seconds, right under it.
    const std::vector<core::ChannelDescriptor> pair{{"stiff", "", core::ChannelKind::Strain},
                                                    {"soft", "", core::ChannelKind::Strain}};
    auto buffer = std::make_shared<core::LiveBuffer>(2, 20000);
    for (std::uint64_t first = 0; first < 4000; first += 10) {
        core::SampleBlock block(2, 10, static_cast<double>(first) * 0.002, 0.002, first);
        for (std::size_t i = 0; i < 10; ++i) {
            const double high = block.timeAt_s(i) < 2.0 ? 1.0 : 0.0;
            block.channel(0)[i] = 400e-6 * high;
            block.channel(1)[i] = 150e-6 * high;
        }
        buffer->consume(block);
    }
    ui::LivePlotWidget plot;
    plot.resize(280, 150);  // as small as the palpation view's force lane
    plot.show();
    plot.setSource(buffer, pair, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 4000u && plot.drawnPointCount(0) > 0; }, 2000));
    tactiscope::testing::runEventLoopFor(150);

    auto* customPlot = plot.findChild<QCustomPlot*>();
    ASSERT_NE(customPlot, nullptr);
    ASSERT_TRUE(customPlot->legend->visible());
    const QRect legend = customPlot->legend->outerRect();
    ASSERT_GT(legend.height(), 0);
    int points = 0;
    for (int g = 0; g < customPlot->graphCount(); ++g) {
        const QCPGraph* graph = customPlot->graph(g);
        for (auto point = graph->data()->constBegin(); point != graph->data()->constEnd(); ++point) {
            if (std::isnan(point->value)) continue;
            const QPointF pixel(graph->keyAxis()->coordToPixel(point->key),
                                graph->valueAxis()->coordToPixel(point->value));
            EXPECT_FALSE(legend.contains(pixel.toPoint())) << "t = " << point->key << " s";
            ++points;
        }
    }
    EXPECT_GT(points, 100);
    EXPECT_FALSE(saveScreenshot(plot, QStringLiteral("live-plot-legend")).isEmpty());
}

// Issue 52: a probe sending its own decisions beside its strains had its
// strain lane 40 px tall under a legend of seven entries. The lane the
// legend sits over gets twice the room of the others.
TEST(LivePlotWidget, TheLaneUnderTheLegendHasRoomForItsTraces)
{
    std::vector<core::ChannelDescriptor> channels;
    for (int c = 0; c < 7; ++c) channels.push_back({"s" + std::to_string(c), "", core::ChannelKind::Strain});
    channels.push_back({"beam", "F", core::ChannelKind::Capacitance});
    channels.push_back({"decision", "", core::ChannelKind::Decision});
    auto buffer = std::make_shared<core::LiveBuffer>(channels.size(), 20000);
    for (std::uint64_t first = 0; first < 1000; first += 10) {
        core::SampleBlock block(channels.size(), 10, static_cast<double>(first) * 0.002, 0.002, first);
        for (std::size_t c = 0; c < channels.size(); ++c)
            for (std::size_t i = 0; i < 10; ++i) block.channel(c)[i] = 1e-6 * static_cast<double>(c + i);
        buffer->consume(block);
    }
    ui::LivePlotWidget plot;
    plot.resize(700, 420);
    plot.show();
    plot.setSource(buffer, channels, 500.0);
    ASSERT_TRUE(waitFor([&] { return plot.samplesReceived() == 1000u; }, 2000));
    tactiscope::testing::runEventLoopFor(150);
    auto* customPlot = plot.findChild<QCustomPlot*>();
    ASSERT_NE(customPlot, nullptr);
    const auto rects = customPlot->axisRects();
    ASSERT_EQ(rects.size(), 3);
    ASSERT_TRUE(customPlot->legend->visible());
    EXPECT_GE(rects[0]->height(), 2 * customPlot->legend->outerRect().height())
        << "strain lane " << rects[0]->height() << " px under a legend of " << customPlot->legend->outerRect().height();
    EXPECT_GT(rects[0]->height(), rects[1]->height()) << "plot " << customPlot->height() << " px";
}
