// The stability test: settled, drifting and noisy signals.
#include "core/calibration/StabilityMonitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tactiscope::core::calibration;

namespace {

// 10 s at 10 Hz of value(t).
template <typename F>
std::pair<std::vector<double>, std::vector<double>> series(F value)
{
    std::vector<double> t, v;
    for (int i = 0; i < 100; ++i) {
        t.push_back(i * 0.1);
        v.push_back(value(i * 0.1));
    }
    return {t, v};
}

const StabilitySettings kSettings{2.0, 0.01, 0.02};

}  // namespace

TEST(StabilityMonitor, ASettledSignalIsStableAfterOneWindow)
{
    std::mt19937 random(1);
    std::normal_distribution<double> noise(0.0, 0.005);
    const auto [t, v] = series([&](double) { return 51.44 + noise(random); });
    const auto w = firstStableWindow(t, v, kSettings);
    ASSERT_TRUE(w.has_value());
    EXPECT_NEAR(w->start_s, 0.0, 1e-12);
    EXPECT_NEAR(w->end_s, 2.0, 1e-12);
    EXPECT_NEAR(w->mean, 51.44, 0.005);
    EXPECT_NEAR(w->sigma, 0.005, 0.002);
}

TEST(StabilityMonitor, WaitsUntilASettlingStepHasSettled)
{
    // A step that settles with a 0.5 s time constant from t = 0.
    const auto [t, v] = series([](double s) { return 1.0 - std::exp(-s / 0.5); });
    const auto w = firstStableWindow(t, v, kSettings);
    ASSERT_TRUE(w.has_value());
    // The drift e^(−t/τ)/τ falls below 0.01 per second at τ·ln(200) = 2.65 s;
    // the first window whose fitted slope passes must reach beyond it.
    EXPECT_GT(w->end_s, 0.5 * std::log(200.0));
    EXPECT_LT(std::abs(w->drift_per_s), 0.01);
    EXPECT_NEAR(w->mean, 1.0, 0.03);
}

TEST(StabilityMonitor, DriftOrNoiseKeepsItUnstable)
{
    const auto [t, drifting] = series([](double s) { return 0.05 * s; });
    EXPECT_FALSE(firstStableWindow(t, drifting, kSettings).has_value());
    std::mt19937 random(2);
    std::normal_distribution<double> noise(0.0, 0.1);
    const auto [t2, noisy] = series([&](double) { return noise(random); });
    EXPECT_FALSE(firstStableWindow(t2, noisy, kSettings).has_value());
}

TEST(StabilityMonitor, AddingInABatchThenJudgingEqualsPushingEachSample)
{
    const auto [t, v] = series([](double s) { return 1.0 - std::exp(-s / 0.5); });
    StabilityMonitor pushed(kSettings), batched(kSettings);
    std::optional<WindowStatistics> last;
    for (std::size_t i = 0; i < t.size(); ++i) {
        last = pushed.push(t[i], v[i]);
        batched.add(t[i], v[i]);
    }
    const auto judged = batched.statistics();
    ASSERT_TRUE(last && judged);
    EXPECT_EQ(judged->mean, last->mean);
    EXPECT_EQ(judged->drift_per_s, last->drift_per_s);
    EXPECT_EQ(judged->count, last->count);
    EXPECT_FALSE(StabilityMonitor(kSettings).statistics());
}

TEST(StabilityMonitor, TheMeansStandardErrorIsSigmaOverRootNWidenedForCorrelatedSamples)
{
    // Independent samples: σ/√n, 0.005/√100 = 0.0005, within its own scatter.
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0.0, 0.005);
    std::vector<double> white(4000);
    for (double& x : white) x = noise(random);
    EXPECT_NEAR(meanStandardError(white), 0.005 / std::sqrt(4000.0), 0.05 * 0.005 / std::sqrt(4000.0));
    // AR(1) with ρ = 0.8: the mean's variance is σ²/n·(1+ρ)/(1−ρ), 9 times
    // that of as many independent samples.
    std::vector<double> filtered(white.size());
    double state = 0.0;
    for (std::size_t i = 0; i < white.size(); ++i) filtered[i] = state = 0.8 * state + white[i];
    const double sigma = 0.005 / std::sqrt(1.0 - 0.64);
    EXPECT_NEAR(meanStandardError(filtered), 3.0 * sigma / std::sqrt(4000.0), 0.15 * 3.0 * sigma / std::sqrt(4000.0));
    EXPECT_EQ(meanStandardError(std::vector<double>{1.0, 2.0}), 0.0);
}
