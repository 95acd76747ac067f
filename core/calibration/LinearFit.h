// Ordinary least squares y = intercept + slope·x, with the statistics a
// calibration report needs: R², residuals and standard errors.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core::calibration {

struct LinearFit {
    double slope = 0.0;
    double intercept = 0.0;
    double rSquared = 0.0;
    double slopeStandardError = 0.0;  // needs ≥ 3 points; 0 with 2
    double interceptStandardError = 0.0;
    double residualStandardDeviation = 0.0;
    // Weighted fits only: √(χ²/(n − 2)) of the residuals against the points'
    // own uncertainties (1 when they scatter as much as they claim); 0 for
    // an ordinary fit.
    double birgeRatio = 0.0;
    std::vector<double> residuals;  // y − fit, per point
    std::size_t points = 0;
};

// Throws std::invalid_argument for fewer than two points, unequal lengths or
// all x equal.
LinearFit fitLine(std::span<const double> x, std::span<const double> y);

// Weighted least squares, each y with its standard uncertainty u (> 0).
// The slope's and intercept's standard errors are propagated from the u's
// and scaled up by the Birge ratio when the points scatter more than their
// u's allow (never down: with a few points a small χ² is luck, not
// precision). Throws std::invalid_argument as fitLine, and for a u that is
// not positive and finite.
LinearFit fitLineWithUncertainties(std::span<const double> x, std::span<const double> y, std::span<const double> u);

// Least squares through the origin, y = slope·x (intercept 0).
LinearFit fitProportional(std::span<const double> x, std::span<const double> y);

}  // namespace tactiscope::core::calibration
