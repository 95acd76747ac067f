// Whether a calibration fit may be trusted, before anyone stores it: enough
// points, a high enough R², and no point far off the line. "Far off" is
// judged against the line fitted through the *other* points (leave one
// out), because a single bad point drags a least-squares line towards
// itself and hides in its own residual; and it is measured as a fraction of
// the full-scale span of y, so sensor noise far below what matters never
// refuses a calibration.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

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
    // The point farthest off the line through the others (none with fewer
    // than three points), and whether it is beyond the limit.
    std::optional<OffLinePoint> farthest;
    bool tooFewPoints = false;
    bool rSquaredTooLow = false;
    bool pointOffLine = false;

    bool credible() const { return !tooFewPoints && !rSquaredTooLow && !pointOffLine; }
};

// Judges the straight-line fit y = a + b·x of the given points. Throws
// std::invalid_argument when x and y differ in length.
FitCredibility judgeFit(std::span<const double> x, std::span<const double> y, const CredibilityLimits& limits);

}  // namespace tactiscope::core::calibration
