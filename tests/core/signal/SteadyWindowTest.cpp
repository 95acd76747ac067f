// The steady window the tare rules read: its statistics by hand on short
// series, and a score near 1 on steady noise and large on a step.
#include "core/signal/SteadyWindow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using tactiscope::core::signal::SteadyWindow;

TEST(SteadyWindow, MeanSpreadAndShiftOfTheLastSamplesOnly)
{
    SteadyWindow window(4);
    for (const double v : {100.0, 1.0, 2.0, 3.0}) window.push(v);
    EXPECT_TRUE(window.full());
    EXPECT_DOUBLE_EQ(window.mean(), 26.5);
    window.push(6.0);  // 100 leaves: 1, 2, 3, 6
    EXPECT_DOUBLE_EQ(window.mean(), 3.0);
    EXPECT_DOUBLE_EQ(window.spread(), 5.0);
    EXPECT_DOUBLE_EQ(window.halfShift(), 4.5 - 1.5);
    // Halves {1, 2} and {3, 6}: sample variances 0.5 and 4.5, so the shift's
    // standard error is √(0.5/2 + 4.5/2) = √2.5.
    EXPECT_NEAR(window.halfShiftScore(), 3.0 / std::sqrt(2.5), 1e-12);
}

TEST(SteadyWindow, NoiselessSignalsScoreZeroWhenStillAndInfiniteWhenMoved)
{
    SteadyWindow still(6), moved(6);
    for (int i = 0; i < 6; ++i) {
        still.push(5.0);
        moved.push(i < 3 ? 5.0 : 6.0);
    }
    EXPECT_EQ(still.halfShiftScore(), 0.0);
    EXPECT_TRUE(std::isinf(moved.halfShiftScore()));
}

TEST(SteadyWindow, SteadyNoiseScoresAboutOneAndAStepFarMore)
{
    std::mt19937_64 random(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    SteadyWindow steady(500), step(500);
    double scoreSum = 0.0;
    constexpr int kTrials = 200;
    for (int trial = 0; trial < kTrials; ++trial) {
        steady.clear();
        for (int i = 0; i < 500; ++i) steady.push(noise(random));
        scoreSum += steady.halfShiftScore();
    }
    // |N(0, 1)| has mean √(2/π) ≈ 0.80.
    EXPECT_NEAR(scoreSum / kTrials, std::sqrt(2.0 / std::numbers::pi), 0.15);
    // A step of one noise σ half way: shift 1, standard error √(2/250) ≈ 0.09.
    for (int i = 0; i < 500; ++i) step.push(noise(random) + (i < 250 ? 0.0 : 1.0));
    EXPECT_GT(step.halfShiftScore(), 6.0);
    EXPECT_NEAR(step.halfShift(), 1.0, 0.3);
}

// A step in a short window, off its middle (a weight lifted 0.3 s into
// five samples at 10 Hz): the halves, each holding some of both levels,
// do not see it; the scan over every split does. On white noise its
// largest score stays far below the steadiness rule's 6.
TEST(SteadyWindow, TheStepScoreFindsAStepAnywhereAndStaysLowOnNoise)
{
    std::mt19937_64 random(3);
    std::normal_distribution<double> noise(0.0, 1e-3);
    SteadyWindow shortWindow(5);
    for (int i = 0; i < 5; ++i) shortWindow.push((i < 3 ? 51.74 : 51.44) + noise(random));
    EXPECT_LT(shortWindow.halfShiftScore(), 6.0);
    EXPECT_GT(shortWindow.stepScore(), 6.0);
    SteadyWindow steady(500);
    double largest = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        steady.clear();
        for (int i = 0; i < 500; ++i) steady.push(noise(random));
        largest = std::max(largest, steady.stepScore());
    }
    EXPECT_LT(largest, 6.0);
    EXPECT_GT(largest, 2.0);  // the largest of many splits' scores, not one's
    SteadyWindow still(4), moved(4);
    for (const double v : {1.0, 1.0, 1.0, 1.0}) still.push(v);
    for (const double v : {1.0, 1.0, 2.0, 2.0}) moved.push(v);
    EXPECT_EQ(still.stepScore(), 0.0);
    EXPECT_TRUE(std::isinf(moved.stepScore()));
}
