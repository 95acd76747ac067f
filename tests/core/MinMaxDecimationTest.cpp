// Min/max decimation against a brute-force per-column scan.
#include "core/signal/MinMaxDecimation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <ranges>
#include <stdexcept>
#include <vector>

using tactiscope::core::signal::decimateMinMax;

TEST(MinMaxDecimation, ReturnsSparseDataUnchanged)
{
    const std::vector<double> t{0.0, 0.1, 0.2, 0.3};
    const std::vector<double> y{1.0, -2.0, 3.0, 0.5};
    std::vector<double> tOut, yOut;
    decimateMinMax(t, y, 0.1, tOut, yOut);
    EXPECT_EQ(tOut, t);
    EXPECT_EQ(yOut, y);
}

TEST(MinMaxDecimation, KeepsExactlyEachColumnsMinimumAndMaximumInTimeOrder)
{
    // 10 s at 500 Hz of noise with a few spikes, onto 300 columns.
    std::mt19937 random(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    const double dt = 0.002;
    const double width = 10.0 / 300.0;
    std::vector<double> t(5000), y(5000);
    for (std::size_t i = 0; i < t.size(); ++i) {
        t[i] = 3.0 + static_cast<double>(i) * dt;
        y[i] = noise(random);
    }
    y[1234] = 40.0;
    y[4321] = -40.0;

    std::vector<double> tOut, yOut;
    decimateMinMax(t, y, width, tOut, yOut);

    // Brute force: the extremes of each column, keyed by column number.
    std::map<long, std::pair<double, double>> expected;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const long column = static_cast<long>(std::floor(t[i] / width));
        auto [it, inserted] = expected.try_emplace(column, y[i], y[i]);
        if (!inserted) {
            it->second.first = std::min(it->second.first, y[i]);
            it->second.second = std::max(it->second.second, y[i]);
        }
    }
    std::map<long, std::vector<double>> produced;
    for (std::size_t i = 0; i < tOut.size(); ++i) {
        produced[static_cast<long>(std::floor(tOut[i] / width))].push_back(yOut[i]);
    }

    ASSERT_EQ(produced.size(), expected.size());
    EXPECT_LE(tOut.size(), 2 * expected.size());
    for (const auto& [column, extremes] : expected) {
        const auto& values = produced.at(column);
        EXPECT_EQ(*std::min_element(values.begin(), values.end()), extremes.first) << "column " << column;
        EXPECT_EQ(*std::max_element(values.begin(), values.end()), extremes.second) << "column " << column;
    }
    EXPECT_TRUE(std::is_sorted(tOut.begin(), tOut.end()));
    EXPECT_EQ(*std::max_element(yOut.begin(), yOut.end()), 40.0);
    EXPECT_EQ(*std::min_element(yOut.begin(), yOut.end()), -40.0);
}

TEST(MinMaxDecimation, ColumnsStayPutWhenTheWindowSlides)
{
    // The same samples seen from two windows that start one sample apart
    // must give identical points wherever the windows overlap.
    std::vector<double> t(4000), y(4000);
    for (std::size_t i = 0; i < t.size(); ++i) {
        t[i] = static_cast<double>(i) * 0.002;
        y[i] = std::sin(0.05 * static_cast<double>(i)) + 0.1 * std::sin(1.7 * static_cast<double>(i));
    }
    std::vector<double> tA, yA, tB, yB;
    decimateMinMax(std::span(t).subspan(0, 3000), std::span(y).subspan(0, 3000), 0.05, tA, yA);
    decimateMinMax(std::span(t).subspan(1, 3000), std::span(y).subspan(1, 3000), 0.05, tB, yB);
    // Skip the first column of B (it lost one sample) and compare the middle.
    for (std::size_t i = 0; i < tA.size(); ++i) {
        if (tA[i] < 0.1 || tA[i] > 5.9) continue;
        const auto at = std::find(tB.begin(), tB.end(), tA[i]);
        ASSERT_NE(at, tB.end()) << "point at t=" << tA[i] << " moved";
        EXPECT_EQ(yB[static_cast<std::size_t>(at - tB.begin())], yA[i]);
    }
}

TEST(MinMaxDecimation, RejectsMismatchedInput)
{
    std::vector<double> t{0.0, 1.0}, y{0.0}, tOut, yOut;
    EXPECT_THROW(decimateMinMax(t, y, 0.1, tOut, yOut), std::invalid_argument);
    y.push_back(1.0);
    EXPECT_THROW(decimateMinMax(t, y, 0.0, tOut, yOut), std::invalid_argument);
}

TEST(MinMaxDecimation, NaNIsNoValueAndAColumnOfOnlyNaNBreaksTheLine)
{
    // 10 columns of 10 samples: column 0 all NaN, column 1 starts with NaN,
    // column 2 has NaN between its extremes.
    std::vector<double> t(100), y(100);
    for (std::size_t i = 0; i < t.size(); ++i) {
        t[i] = static_cast<double>(i) * 0.1 + 0.05;
        y[i] = static_cast<double>(i % 7);
    }
    for (std::size_t i = 0; i < 10; ++i) y[i] = std::nan("");
    y[10] = std::nan("");
    y[11] = -5.0;
    y[18] = 9.0;
    y[25] = std::nan("");
    std::vector<double> tOut, yOut;
    decimateMinMax(t, y, 1.0, tOut, yOut);
    ASSERT_GE(yOut.size(), 5u);
    EXPECT_EQ(tOut[0], t[0]);
    EXPECT_TRUE(std::isnan(yOut[0]));  // one point for the empty column
    EXPECT_EQ(tOut[1], t[11]);
    EXPECT_EQ(yOut[1], -5.0);
    EXPECT_EQ(tOut[2], t[18]);
    EXPECT_EQ(yOut[2], 9.0);
    // Column 2 (samples 20–29, values 6,0,1,2,3,NaN,5,6,0,1): 0 at 21, 6 at 20.
    EXPECT_EQ(tOut[3], t[20]);
    EXPECT_EQ(tOut[4], t[21]);
    for (const double v : yOut | std::views::drop(1)) EXPECT_FALSE(std::isnan(v));
}

TEST(MinMaxDecimation, AStepLongerThanTheLimitIsAGapAndBreaksTheLine)
{
    // Samples every 2 ms, with 0.010 → 0.100 s lost.
    std::vector<double> t{0.000, 0.002, 0.004, 0.006, 0.008, 0.010, 0.100, 0.102};
    std::vector<double> y{1, 2, 3, 4, 5, 6, 7, 8};
    const auto gaps = tactiscope::core::signal::gapsIn(t, 0.003);
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_EQ(gaps[0].from_s, 0.010);
    EXPECT_EQ(gaps[0].to_s, 0.100);
    tactiscope::core::signal::breakAtGaps(t, y, 0.003);
    ASSERT_EQ(t.size(), 9u);
    EXPECT_EQ(t[6], 0.055);
    EXPECT_TRUE(std::isnan(y[6]));
    EXPECT_EQ(y[7], 7.0);
    EXPECT_TRUE(tactiscope::core::signal::gapsIn(t, 0.1).empty());
}
