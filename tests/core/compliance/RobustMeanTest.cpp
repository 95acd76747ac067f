// Iterative 3σ rejection with planted outliers.
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
    // Iterating trims a normal sample's tails a little each round (the kept
    // values' σ shrinks), settling near 0.5 %: allow 1 % of the good values.
    EXPECT_LE(r.rejected, 20u);
    EXPECT_NEAR(r.mean, 10.0, 0.02);
    EXPECT_NEAR(r.standardDeviation, 0.1, 0.01);
    EXPECT_NEAR(r.standardError, r.standardDeviation / std::sqrt(static_cast<double>(r.used)), 1e-15);
}

TEST(RobustMean, NeedsIterationWhenOneOutlierHidesAnother)
{
    // 30 values at 0 and ±1, one at 8 and one at 60. The first pass's σ is
    // inflated by 60 and keeps 8; only after 60 is gone does 8 stand out.
    std::vector<double> values;
    for (int i = 0; i < 10; ++i) values.insert(values.end(), {-1.0, 0.0, 1.0});
    values.push_back(8.0);
    values.push_back(60.0);
    const auto r = robustMean(values);
    EXPECT_EQ(r.rejected, 2u);
    EXPECT_NEAR(r.mean, 0.0, 1e-15);
}

TEST(RobustMean, SmallSamplesCannotRejectAnything)
{
    // n = 5 with one wild value: its own deviation inflates σ so much that
    // |x − mean| ≤ 3σ always holds (a known limit of the k·σ rule).
    const std::vector<double> values{1, 2, 3, 4, 100};
    EXPECT_EQ(robustMean(values).rejected, 0u);
    EXPECT_THROW(robustMean(std::vector<double>{}), std::invalid_argument);
}
