// Least squares against a hand-made data set with known residuals.
#include "core/calibration/LinearFit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace tactiscope::core::calibration;

TEST(LinearFit, RecoversALineWithKnownResiduals)
{
    // y = 1 + 2x with residuals (+0.1, −0.1, −0.1, +0.1), which sum to zero
    // and are orthogonal to x, so the fit is exactly 1 + 2x.
    const std::vector<double> x{0, 1, 2, 3}, y{1.1, 2.9, 4.9, 7.1};
    const LinearFit fit = fitLine(x, y);
    EXPECT_NEAR(fit.slope, 2.0, 1e-14);
    EXPECT_NEAR(fit.intercept, 1.0, 1e-14);
    EXPECT_NEAR(fit.residuals[0], 0.1, 1e-14);
    EXPECT_NEAR(fit.residuals[2], -0.1, 1e-14);
    // SS_res = 0.04, SS_tot = 20.04; s² = 0.04/2, S_xx = 5.
    EXPECT_NEAR(fit.rSquared, 1.0 - 0.04 / 20.04, 1e-14);
    EXPECT_NEAR(fit.slopeStandardError, std::sqrt(0.02 / 5.0), 1e-14);
    EXPECT_NEAR(fit.interceptStandardError, std::sqrt(0.02 * (0.25 + 2.25 / 5.0)), 1e-14);
    EXPECT_EQ(fit.points, 4u);
}

TEST(LinearFit, ProportionalFitGoesThroughTheOrigin)
{
    const std::vector<double> x{1, 2, 4}, y{2, 4, 8.4};
    const LinearFit fit = fitProportional(x, y);
    EXPECT_NEAR(fit.slope, (2 + 8 + 33.6) / 21.0, 1e-14);  // Σxy/Σx²
    EXPECT_EQ(fit.intercept, 0.0);
}

TEST(LinearFit, RefusesDegenerateData)
{
    EXPECT_THROW(fitLine(std::vector<double>{1.0}, std::vector<double>{2.0}), std::invalid_argument);
    EXPECT_THROW(fitLine(std::vector<double>{1.0, 1.0}, std::vector<double>{2.0, 3.0}), std::invalid_argument);
    EXPECT_THROW(fitLine(std::vector<double>{1.0, 2.0}, std::vector<double>{2.0}), std::invalid_argument);
}

TEST(LinearFit, AWeightedFitPropagatesThePointsUncertainties)
{
    // The residuals (+0.1, −0.1, −0.1, +0.1) again, each point claiming
    // u = 0.2: χ² = 4·0.25 = 1 over 2 degrees of freedom, a Birge ratio of
    // √0.5, so the slope's standard error is the propagated u/√S_xx = 0.2/√5,
    // not scaled down.
    const std::vector<double> x{0, 1, 2, 3}, y{1.1, 2.9, 4.9, 7.1}, u{0.2, 0.2, 0.2, 0.2};
    const LinearFit fit = fitLineWithUncertainties(x, y, u);
    EXPECT_NEAR(fit.slope, 2.0, 1e-14);
    EXPECT_NEAR(fit.intercept, 1.0, 1e-14);
    EXPECT_NEAR(fit.birgeRatio, std::sqrt(0.5), 1e-14);
    EXPECT_NEAR(fit.slopeStandardError, 0.2 / std::sqrt(5.0), 1e-14);
    // Claiming u = 0.05, the points scatter twice as much as they claim:
    // χ² = 16 over 2, Birge √8, and the error is scaled up by it.
    const std::vector<double> small{0.05, 0.05, 0.05, 0.05};
    const LinearFit scaled = fitLineWithUncertainties(x, y, small);
    EXPECT_NEAR(scaled.birgeRatio, std::sqrt(8.0), 1e-12);
    EXPECT_NEAR(scaled.slopeStandardError, std::sqrt(8.0) * 0.05 / std::sqrt(5.0), 1e-14);
}

TEST(LinearFit, AWeightedFitFollowsThePreciseOnes)
{
    // Three exact points on y = x and one far off but claiming a huge u: the
    // line goes through the exact ones (weights 1 against 10⁻⁸).
    const std::vector<double> x{0, 1, 2, 3}, y{0, 1, 2, 30}, u{1e-3, 1e-3, 1e-3, 10.0};
    const LinearFit fit = fitLineWithUncertainties(x, y, u);
    EXPECT_NEAR(fit.slope, 1.0, 1e-6);
    EXPECT_THROW(fitLineWithUncertainties(x, y, std::vector<double>{1, 1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(fitLineWithUncertainties(x, y, std::vector<double>{1, 1, 1}), std::invalid_argument);
}
