// Detector parameters: the paper's defaults, lag rounding and validation.
#include "core/detector/DetectorParameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace tactiscope::core::detector;

TEST(DetectorParameters, DefaultsAreThePapersSettings)
{
    const DetectorParameters p;
    ASSERT_EQ(p.lags_s.size(), 75u);  // 2, 4, …, 150 ms
    EXPECT_DOUBLE_EQ(p.lags_s.front(), 0.002);
    EXPECT_NEAR(p.lags_s.back(), 0.150, 1e-15);
    const auto r = resolve(p);
    EXPECT_EQ(r.lags.front(), 1u);
    EXPECT_EQ(r.lags.back(), 75u);
    EXPECT_DOUBLE_EQ(r.forgetting.front(), std::exp(-1.0));           // λ = c = Δt
    EXPECT_DOUBLE_EQ(r.forgetting.back(), std::exp(-0.002 / 0.150));  // λ = c = 150 ms
    EXPECT_DOUBLE_EQ(r.epsilonSquared, 49e-12);
    EXPECT_EQ(r.window, 0u);
}

TEST(DetectorParameters, LagsRoundToWholeSamplesOnce)
{
    DetectorParameters p;
    p.lags_s = lagRange_s(0.002, 0.012, 0.003);                            // 2, 5, 8, 11 ms at Δt = 2 ms
    EXPECT_EQ(resolve(p).lags, (std::vector<std::uint32_t>{1, 3, 4, 6}));  // 2.5 and 5.5 round away from zero
    p.lags_s = {0.004, 0.0041, 0.002};
    EXPECT_EQ(resolve(p).lags, (std::vector<std::uint32_t>{1, 2}));
}

TEST(DetectorParameters, RejectsWhatCannotBeComputed)
{
    const auto bad = [](auto change) {
        DetectorParameters p;
        change(p);
        return p;
    };
    EXPECT_THROW(resolve(bad([](auto& p) { p.lags_s = {}; })), std::invalid_argument);
    EXPECT_THROW(resolve(bad([](auto& p) { p.lags_s = {0.0009}; })), std::invalid_argument);
    EXPECT_THROW(resolve(bad([](auto& p) { p.epsilon = 0.0; })), std::invalid_argument);
    EXPECT_THROW(resolve(bad([](auto& p) { p.threshold = 1.0; })), std::invalid_argument);
    EXPECT_THROW(resolve(bad([](auto& p) { p.sampleInterval_s = -1.0; })), std::invalid_argument);
    EXPECT_THROW(resolve(bad([](auto& p) { p.window_s = 0.001; })), std::invalid_argument);
    EXPECT_THROW(lagRange_s(0.010, 0.002, 0.002), std::invalid_argument);
    EXPECT_THROW(lagRange_s(0.002, 0.010, 0.0), std::invalid_argument);
}

// Issue 52: the shortest recording the detector judges, by hand: the
// longest lag plus three of its forgetting times (λ = c: 0.15 + 0.45 s), a
// fixed λ's three times (0.15 + 3 × 0.1 s), or the sliding window.
TEST(DetectorParameters, TheShortestJudgedRecordingIsTheLongestLagAndItsSettling)
{
    DetectorParameters p;
    EXPECT_NEAR(shortestJudged_s(p), 0.6, 1e-12);
    p.lambdaRule = LambdaRule::Fixed;
    p.fixedLambda_s = 0.1;
    EXPECT_NEAR(shortestJudged_s(p), 0.45, 1e-12);
    p.window_s = 0.2;
    EXPECT_NEAR(shortestJudged_s(p), 0.35, 1e-12);
    p = DetectorParameters{};
    p.lags_s = lagRange_s(0.01, 0.05, 0.01);
    EXPECT_NEAR(shortestJudged_s(p), 0.2, 1e-12);
}
