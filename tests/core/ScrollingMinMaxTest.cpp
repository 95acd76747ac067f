// ScrollingMinMax against decimateMinMax over the same window: fed in
// random chunks with NaN among the samples, then scrolled, its closed
// columns are exactly the batch decimation's.
#include "core/signal/ScrollingMinMax.h"

#include "core/signal/MinMaxDecimation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tactiscope::core::signal::decimateMinMax;
using tactiscope::core::signal::ScrollingMinMax;

TEST(ScrollingMinMax, ItsClosedColumnsAreTheBatchDecimationOfTheWindow)
{
    // 30 s at 2 kHz, columns of 6.25 ms (a 10 s window on 1600 px).
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> chunk(1, 120);
    const double dt = 0.0005, width = 10.0 / 1600.0;
    std::vector<double> t(60000), y(60000);
    for (std::size_t i = 0; i < t.size(); ++i) {
        t[i] = 100.0 + static_cast<double>(i) * dt;
        y[i] = std::sin(t[i]) + 0.1 * noise(random);
    }
    for (std::size_t i = 20000; i < 20040; ++i) y[i] = std::nan("");  // a gap across whole columns
    y[30001] = std::nan("");

    ScrollingMinMax scrolling(width);
    for (std::size_t first = 0; first < t.size();) {
        const std::size_t n = std::min(chunk(random), t.size() - first);
        scrolling.append(std::span(t).subspan(first, n), std::span(y).subspan(first, n));
        first += n;
    }
    const double start = t.back() - 10.0;
    scrolling.dropBefore(start);
    std::vector<double> gotT, gotY;
    scrolling.points(gotT, gotY);

    // The batch decimation of the closed columns: from the start of the
    // column holding `start` to the start of the last column.
    const double firstColumn = std::floor(start / width), lastColumn = std::floor(t.back() / width);
    std::vector<double> windowT, windowY;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double column = std::floor(t[i] / width);
        if (column >= firstColumn && column < lastColumn) {
            windowT.push_back(t[i]);
            windowY.push_back(y[i]);
        }
    }
    std::vector<double> wantT, wantY;
    decimateMinMax(windowT, windowY, width, wantT, wantY);
    ASSERT_GT(gotT.size(), wantT.size());  // and the open column after them
    ASSERT_LT(gotT.size(), wantT.size() + 20);
    for (std::size_t i = 0; i < wantT.size(); ++i) {
        ASSERT_EQ(gotT[i], wantT[i]) << i;
        if (std::isnan(wantY[i]))
            ASSERT_TRUE(std::isnan(gotY[i])) << i;
        else
            ASSERT_EQ(gotY[i], wantY[i]) << i;
    }
    EXPECT_GE(gotT[wantT.size()], lastColumn * width);
}

TEST(ScrollingMinMax, RefusesAZeroColumnWidth)
{
    EXPECT_THROW(ScrollingMinMax(0.0), std::invalid_argument);
}
