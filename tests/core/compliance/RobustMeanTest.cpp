// The paper's 3σ rejection, once, with planted outliers.
#include "core/compliance/RobustMean.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

using tactiscope::core::compliance::robustMean;

TEST(RobustMean, RejectsPlantedOutliersAndKeepsTheRest)
{
    std::mt19937 random(3);
    std::normal_distribution<double> noise(10.0, 0.1);
    std::vector<double> values(1000);
    for (double& v : values) v = noise(random);
    for (std::size_t i = 0; i < 10; ++i) values[i * 97] = 20.0 + static_cast<double>(i);  // ten gross outliers
    const auto r = robustMean(values);
    EXPECT_GE(r.rejected, 10u);  // the ten at least
    // The ten inflate the first σ (to about 1.5), so no good value lies
    // beyond 3σ of it: one pass rejects exactly the planted ones.
    EXPECT_EQ(r.rejected, 10u);
    EXPECT_NEAR(r.mean, 10.0, 0.02);
    EXPECT_NEAR(r.standardDeviation, 0.1, 0.01);
    EXPECT_NEAR(r.standardError, r.standardDeviation / std::sqrt(static_cast<double>(r.used)), 1e-15);
}

TEST(RobustMean, RejectsOnceAsThePaperDoes)
{
    // 30 values at 0 and ±1, one at 8 and one at 60. The pass's σ is
    // inflated by 60 (mean 2.13, σ 10.7), so 8 stays: the paper rejects
    // once, and the mean and σ are those of the 31 kept values.
    std::vector<double> values;
    for (int i = 0; i < 10; ++i) values.insert(values.end(), {-1.0, 0.0, 1.0});
    values.push_back(8.0);
    values.push_back(60.0);
    const auto r = robustMean(values);
    EXPECT_EQ(r.rejected, 1u);
    EXPECT_EQ(r.used, 31u);
    EXPECT_NEAR(r.mean, 8.0 / 31.0, 1e-15);
    // Σ(x − 8/31)² over the kept: 20 + 64 − 31·(8/31)² by hand.
    EXPECT_NEAR(r.standardDeviation, std::sqrt((84.0 - 64.0 / 31.0) / 30.0), 1e-12);
}

TEST(RobustMean, SmallSamplesCannotRejectAnything)
{
    // n = 5 with one wild value: its own deviation inflates σ so much that
    // |x − mean| ≤ 3σ always holds (a known limit of the k·σ rule).
    const std::vector<double> values{1, 2, 3, 4, 100};
    EXPECT_EQ(robustMean(values).rejected, 0u);
    EXPECT_THROW(robustMean(std::vector<double>{}), std::invalid_argument);
}
