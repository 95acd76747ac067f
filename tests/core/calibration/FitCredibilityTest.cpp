// Credibility of calibration fits: values worked by hand on small point sets.
#include "core/calibration/FitCredibility.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using namespace tactiscope::core::calibration;

TEST(FitCredibility, PointsOnALineAreCredible)
{
    const std::vector<double> x{0, 1, 2, 3, 4};
    const std::vector<double> y{1, 3, 5, 7, 9};
    const FitCredibility c = judgeFit(x, y, {});
    EXPECT_TRUE(c.credible());
    EXPECT_EQ(c.points, 5u);
    EXPECT_DOUBLE_EQ(c.rSquared, 1.0);
    ASSERT_TRUE(c.farthest);
    EXPECT_NEAR(c.farthest->offLine, 0.0, 1e-12);
    EXPECT_FALSE(c.pointOffLine);
}

TEST(FitCredibility, APointOffTheLineThroughTheOthersIsNamed)
{
    // Without the middle point the others lie on y = 2x exactly, which
    // predicts 4 at x = 2; the point reads 5: off by 1 of a span of 8.
    const std::vector<double> x{0, 1, 2, 3, 4};
    const std::vector<double> y{0, 2, 5, 6, 8};
    CredibilityLimits limits;
    limits.minimumRSquared = 0.9;  // judge the point alone
    const FitCredibility c = judgeFit(x, y, limits);
    ASSERT_TRUE(c.farthest);
    EXPECT_EQ(c.farthest->index, 2u);
    EXPECT_DOUBLE_EQ(c.farthest->offLine, 0.125);
    EXPECT_TRUE(c.pointOffLine);
    EXPECT_FALSE(c.credible());

    limits.maximumOffLine = 0.13;
    EXPECT_TRUE(judgeFit(x, y, limits).credible());
}

TEST(FitCredibility, AnEndPointIsNotBlamedForAnotherPointsError)
{
    // Loads 0, 20, 50, 100, 200 g where the "100 g" reads as 50 g. The line
    // through all but the 200 g point passes far below it (it is pulled by
    // the bad point), yet the others without the bad point lie exactly on
    // y = x: the bad point is the one named, 50 off of a span of 200.
    const std::vector<double> x{0, 20, 50, 100, 200};
    const std::vector<double> y{0, 20, 50, 50, 200};
    const FitCredibility c = judgeFit(x, y, {});
    ASSERT_TRUE(c.farthest);
    EXPECT_EQ(c.farthest->index, 3u);
    EXPECT_DOUBLE_EQ(c.farthest->offLine, 0.25);
    EXPECT_TRUE(c.pointOffLine);
}

TEST(FitCredibility, TooFewPointsAreRefused)
{
    const std::vector<double> x{0, 1, 2};
    const std::vector<double> y{0, 2, 4};
    EXPECT_TRUE(judgeFit(x, y, {}).tooFewPoints);
    CredibilityLimits three;
    three.minimumPoints = 3;
    EXPECT_TRUE(judgeFit(x, y, three).credible());
}

TEST(FitCredibility, ALowRSquaredIsRefused)
{
    // y = x² on 0..3: mean 3.5, SS_tot = 12.25+6.25+0.25+30.25 = 49; the
    // line is y = −1 + 3x, residuals 1, −1, −1, 1, SS_res = 4, R² = 45/49.
    const std::vector<double> x{0, 1, 2, 3};
    const std::vector<double> y{0, 1, 4, 9};
    CredibilityLimits limits;
    limits.maximumOffLine = 1.0;
    const FitCredibility c = judgeFit(x, y, limits);
    EXPECT_DOUBLE_EQ(c.rSquared, 45.0 / 49.0);
    EXPECT_TRUE(c.rSquaredTooLow);
    limits.minimumRSquared = 0.9;
    EXPECT_TRUE(judgeFit(x, y, limits).credible());
}

TEST(FitCredibility, NoLineAtAllIsNotCredible)
{
    const std::vector<double> x{1, 1, 1, 1};
    const std::vector<double> y{0, 1, 2, 3};
    const FitCredibility c = judgeFit(x, y, {});
    EXPECT_TRUE(c.rSquaredTooLow);
    EXPECT_FALSE(c.credible());
    EXPECT_THROW(judgeFit(x, std::vector<double>{1.0}, {}), std::invalid_argument);
}

TEST(FitCredibility, ResidualsAreTakenAsAFractionOfTheSpanOfY)
{
    // y spans 8 (0 to 8): residuals 0.4 and −0.2 are 5 % and −2.5 % of it.
    const std::vector<double> y{0, 2, 5, 6, 8};
    const std::vector<double> residuals{0.0, 0.4, -0.2, 0.0, 0.0};
    const std::vector<double> fractions = residualsOfSpan(residuals, y);
    ASSERT_EQ(fractions.size(), 5u);
    EXPECT_DOUBLE_EQ(fractions[1], 0.05);
    EXPECT_DOUBLE_EQ(fractions[2], -0.025);
    EXPECT_DOUBLE_EQ(fractions[0], 0.0);
}

TEST(FitCredibility, ResidualsOfNoSpanAreNone)
{
    const std::vector<double> flat{3, 3, 3};
    EXPECT_TRUE(residualsOfSpan(std::vector<double>{0.1, 0.0, -0.1}, flat).empty());
    EXPECT_TRUE(residualsOfSpan({}, {}).empty());
    EXPECT_THROW(residualsOfSpan(std::vector<double>{0.1}, flat), std::invalid_argument);
}
