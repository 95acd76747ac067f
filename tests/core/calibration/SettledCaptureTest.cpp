// The capture rule: stable once, then a fresh stable window is the reading.
#include "core/calibration/SettledCapture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

using namespace tactiscope::core::calibration;

namespace {

// A load step at t = 0 settling with τ = 0.3 s, sampled at 100 Hz and
// judged every 50 ms; the kept window, if any, within 10 s.
std::optional<WindowStatistics> captureStep(SettledCapture& capture, double step)
{
    capture.arm();
    for (int i = 0; i < 1000; ++i) {
        const double t = i * 0.01;
        capture.add(t, step * (1.0 - std::exp(-t / 0.3)));
        if (i % 5 == 4)
            if (auto kept = capture.judge()) return kept;
    }
    return std::nullopt;
}

const StabilitySettings kSettings{1.0, 0.5, 1.0};

}  // namespace

TEST(SettledCapture, KeepsTheFreshWindowAfterTheFirstStableOne)
{
    // Step of 100: the line's slope over [t − 1, t] falls below 0.5/s near
    // t ≈ 2.5 s, when that window's mean still lags by about 0.2 (its
    // start's residue 0.7 times τ/1 s). The kept window starts when that
    // one was judged stable, and its mean lags by about
    // 100·τ·(e^(−2.5/τ) − e^(−3.5/τ)) ≈ 0.007.
    SettledCapture capture(kSettings);
    const auto kept = captureStep(capture, 100.0);
    ASSERT_TRUE(kept);
    StabilityMonitor plain(kSettings);
    std::optional<WindowStatistics> first;
    for (int i = 0; i < 1000 && !first; ++i) {
        const double t = i * 0.01;
        if (auto w = plain.push(t, 100.0 * (1.0 - std::exp(-t / 0.3))); w && w->stable) first = w;
    }
    ASSERT_TRUE(first);
    EXPECT_GE(kept->start_s, first->end_s - 0.05);  // judged at most one poll later
    EXPECT_LT(100.0 - kept->mean, 0.02);
    EXPECT_GT(100.0 - first->mean, 10.0 * (100.0 - kept->mean));  // the residue the fresh window avoids
    EXPECT_EQ(capture.phase(), SettledCapture::Phase::Watching);
}

TEST(SettledCapture, WatchingNeverCapturesAndAKnockSendsItBackToSettling)
{
    SettledCapture capture(kSettings);
    for (int i = 0; i < 300; ++i) capture.add(i * 0.01, 5.0);
    EXPECT_FALSE(capture.judge());
    ASSERT_TRUE(capture.latest());
    EXPECT_TRUE(capture.latest()->stable);

    capture.arm();
    EXPECT_FALSE(capture.latest());
    double t = 3.0;
    for (; t < 4.05; t += 0.01) capture.add(t, 5.0);
    EXPECT_FALSE(capture.judge());
    EXPECT_EQ(capture.phase(), SettledCapture::Phase::Averaging);
    // The weight swings during the fresh window: no reading, settle anew.
    for (int i = 0; i < 105; ++i, t += 0.01) capture.add(t, 5.0 + 3.0 * std::sin(40.0 * t));
    EXPECT_FALSE(capture.judge());
    EXPECT_EQ(capture.phase(), SettledCapture::Phase::Settling);
}

// The rule on a recorded series (issue 55: the CLI's steps): the settled
// part begins with the fresh window, the sample after the first stable
// window's last; a series that never settles so gives none.
TEST(SettledCapture, OnARecordedSeriesTheSettledPartBeginsWithTheFreshWindow)
{
    std::vector<double> t, v;
    for (int i = 0; i < 1000; ++i) {
        t.push_back(i * 0.01);
        v.push_back(100.0 * (1.0 - std::exp(-t.back() / 0.3)));
    }
    StabilityMonitor plain(kSettings);
    std::optional<std::size_t> firstEnd;
    for (std::size_t i = 0; i < t.size() && !firstEnd; ++i)
        if (auto w = plain.push(t[i], v[i]); w && w->stable) firstEnd = i;
    ASSERT_TRUE(firstEnd);
    const auto from = settledFrom(t, v, kSettings);
    ASSERT_TRUE(from);
    EXPECT_EQ(*from, *firstEnd + 1);
    EXPECT_LT(100.0 - v[*from], 0.5);  // past the settling's tail
    // Its first three seconds: the fresh window would end past them.
    EXPECT_FALSE(settledFrom(std::span(t).first(300), std::span(v).first(300), kSettings));
}
