// Whether a calibration fit may be trusted, before anyone stores it: enough
// points, a high enough R², and no point far off the line. The suspect
// point is found against the line fitted through the *other* points (leave
// one out, scaled by that line's prediction error: the externally
// studentized residual), because a single bad point drags a least-squares
// line towards itself and hides in its own residual, and an end point
// always lies far from a line fitted without it. Whether the suspect is
// "far off" is then its distance as a fraction of the full-scale span of
// y, so sensor noise far below what matters never refuses a calibration.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::core::calibration {

struct CredibilityLimits {
    std::size_t minimumPoints = 4;  // the zero counts as one
    double minimumRSquared = 0.999;
    double maximumOffLine = 0.02;  // of the full-scale span of y
};

struct OffLinePoint {
    std::size_t index = 0;
    double offLine = 0.0;  // |y − line through the others| / span of y
};

struct FitCredibility {
    std::size_t points = 0;
    double rSquared = 0.0;
    // The most suspect point and its distance from the line through the
    // others (none with fewer than three points).
    std::optional<OffLinePoint> farthest;
    bool tooFewPoints = false;
    bool rSquaredTooLow = false;
    bool pointOffLine = false;

    bool credible() const { return !tooFewPoints && !rSquaredTooLow && !pointOffLine; }
};

// Judges the straight-line fit y = a + b·x of the given points. Throws
// std::invalid_argument when x and y differ in length.
FitCredibility judgeFit(std::span<const double> x, std::span<const double> y, const CredibilityLimits& limits);

// Each point's residual from `residuals` (y − fit) as a fraction of the
// full-scale span of y, the scale the off-line limit is judged on, so a
// wizard's table and its verdict speak of the same number. Empty when y
// spans nothing (a fraction of nothing means nothing). Throws
// std::invalid_argument when the lengths differ.
std::vector<double> residualsOfSpan(std::span<const double> residuals, std::span<const double> y);

}  // namespace tactiscope::core::calibration
