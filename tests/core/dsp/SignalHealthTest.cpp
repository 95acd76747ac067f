// Signal health against injected truth: a drift under noise (and its ±
// covering the truth over seeds as a standard uncertainty must), hum
// levels, clipped samples.
#include "core/dsp/SignalHealth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace tactiscope::core::dsp;

namespace {

// White or AR(1) noise (correlation `phi` sample to sample) of standard deviation sigma.
std::vector<double> driftingNoise(std::size_t n, double rate, double drift_per_s, double sigma, double phi,
                                  unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, sigma * std::sqrt(1.0 - phi * phi));
    std::vector<double> v(n);
    double state = std::normal_distribution<double>(0.0, sigma)(random);
    for (std::size_t i = 0; i < n; ++i) {
        state = phi * state + noise(random);
        v[i] = 40.0 + drift_per_s * static_cast<double>(i) / rate + state;
    }
    return v;
}

ChannelHealth healthOf(const std::vector<double>& v, double rate, std::optional<ChannelRange> range = std::nullopt)
{
    HealthAccumulator health(rate, v.size(), range);
    for (std::size_t at = 0; at < v.size(); at += 4096)
        health.push(std::span(v).subspan(at, std::min<std::size_t>(4096, v.size() - at)));
    return health.result();
}

}  // namespace

TEST(SignalHealth, AnHourOfDriftUnderNoiseReadsItsRate)
{
    // 5 µε/h under 2 µε of white noise, an hour at 100 Hz.
    const double rate = 100.0;
    const auto v = driftingNoise(360000, rate, 5.0 / 3600.0, 2.0, 0.0, 21);
    const ChannelHealth h = healthOf(v, rate);
    ASSERT_TRUE(h.drift.has_value());
    EXPECT_NEAR(h.drift->rate_per_s * 3600.0, 5.0, 0.1);
    EXPECT_LT(h.drift->standardUncertainty_per_s * 3600.0, 0.1);
    EXPECT_EQ(h.clipped, 0u);
    EXPECT_FALSE(h.hum.has_value());
    // White noise of σ at 100 Hz: a density of σ·√(2/fs).
    EXPECT_NEAR(h.noiseFloor_per_sqrt_hz, 2.0 * std::sqrt(2.0 / rate), 0.1 * 2.0 * std::sqrt(2.0 / rate));
}

TEST(SignalHealth, TheDriftsUncertaintyCoversTheTruthAsAStandardUncertainty)
{
    // Over 400 recordings each (white, then correlated noise), ±1u must hold
    // the truth 68.3 % of the time and ±2u 95.4 %, within 3σ binomial limits.
    for (const double phi : {0.0, 0.9}) {
        const int runs = 400;
        int within1 = 0;
        int within2 = 0;
        for (int seed = 0; seed < runs; ++seed) {
            const double truth = 0.02;  // units per second
            const auto v = driftingNoise(12000, 20.0, truth, 1.5, phi, 1000 + static_cast<unsigned>(seed));
            const auto drift = healthOf(v, 20.0).drift;
            ASSERT_TRUE(drift.has_value());
            const double z = std::abs(drift->rate_per_s - truth) / drift->standardUncertainty_per_s;
            within1 += z <= 1.0;
            within2 += z <= 2.0;
        }
        const auto limit = [runs](double p) { return 3.0 * std::sqrt(p * (1.0 - p) / runs); };
        EXPECT_NEAR(within1 / double(runs), 0.683, limit(0.683)) << "phi " << phi;
        EXPECT_NEAR(within2 / double(runs), 0.954, limit(0.954)) << "phi " << phi;
    }
}

TEST(SignalHealth, HumIsReadInTheChannelsUnitWithinTwoPercent)
{
    const double rate = 1000.0;
    for (const double mains : {50.0, 60.0}) {
        auto v = driftingNoise(120000, rate, 0.0, 2.0, 0.0, 31);
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] += 12.0 * std::sin(2.0 * std::numbers::pi * mains * static_cast<double>(i) / rate + 1.0);
        const ChannelHealth h = healthOf(v, rate);
        ASSERT_TRUE(h.hum.has_value());
        EXPECT_EQ(h.hum->mains_hz, mains);
        EXPECT_NEAR(h.hum->amplitude, 12.0, 0.02 * 12.0);
    }
}

TEST(SignalHealth, ClippedSamplesAreTheOnesHeldAtTheExtremes)
{
    const double rate = 500.0;
    std::vector<double> v(20000);
    std::mt19937 random(4);
    std::normal_distribution<double> noise(0.0, 0.5);
    std::size_t beyond = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double x = 100.0 * std::sin(2.0 * std::numbers::pi * 1.3 * static_cast<double>(i) / rate) + noise(random);
        beyond += std::abs(x) >= 90.0;
        v[i] = std::clamp(x, -90.0, 90.0);
    }
    // Without the range, a touch of the limit between noisy samples (a run
    // shorter than three) is not told from the signal: within 2 %.
    EXPECT_NEAR(static_cast<double>(healthOf(v, rate).clipped), static_cast<double>(beyond),
                0.02 * static_cast<double>(beyond));
    EXPECT_EQ(healthOf(v, rate, ChannelRange{-90.0, 90.0}).clipped, beyond);
    // Unclipped noise and a flat channel clip nothing.
    for (double& x : v) x = noise(random);
    EXPECT_EQ(healthOf(v, rate).clipped, 0u);
    std::fill(v.begin(), v.end(), 3.0);
    EXPECT_EQ(healthOf(v, rate).clipped, 0u);
    // Exact steps (a rig's set loads) repeat everywhere: their top is not clipping.
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>((i / 500) % 4);
    EXPECT_EQ(healthOf(v, rate).clipped, 0u);
}

TEST(SignalHealth, MissingSamplesAreCountedAndSkipped)
{
    const double rate = 100.0;
    auto v = driftingNoise(60000, rate, 0.01, 0.5, 0.0, 8);
    for (std::size_t i = 10000; i < 12000; ++i) v[i] = std::nan("");
    const ChannelHealth h = healthOf(v, rate);
    EXPECT_EQ(h.missing, 2000u);
    ASSERT_TRUE(h.drift.has_value());
    EXPECT_NEAR(h.drift->rate_per_s, 0.01, 3.0 * h.drift->standardUncertainty_per_s);
}
