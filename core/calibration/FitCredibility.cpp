// FitCredibility: point count, R², leave-one-out distance from the line.
#include "core/calibration/FitCredibility.h"

#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tactiscope::core::calibration {

FitCredibility judgeFit(std::span<const double> x, std::span<const double> y, const CredibilityLimits& limits)
{
    if (x.size() != y.size()) throw std::invalid_argument("fit credibility: x and y differ in length");
    FitCredibility result;
    result.points = x.size();
    result.tooFewPoints = x.size() < std::max<std::size_t>(limits.minimumPoints, 2);
    try {
        result.rSquared = fitLine(x, y).rSquared;
    } catch (const std::invalid_argument&) {
        result.rSquared = 0.0;  // fewer than two points, or all at one x: no line at all
    }
    result.rSquaredTooLow = result.rSquared < limits.minimumRSquared;

    const auto [low, high] = std::minmax_element(y.begin(), y.end());
    const double span = y.empty() ? 0.0 : *high - *low;
    if (x.size() < 3 || !(span > 0.0)) return result;
    std::vector<double> otherX, otherY;
    for (std::size_t i = 0; i < x.size(); ++i) {
        otherX.clear();
        otherY.clear();
        for (std::size_t j = 0; j < x.size(); ++j) {
            if (j == i) continue;
            otherX.push_back(x[j]);
            otherY.push_back(y[j]);
        }
        LinearFit others;
        try {
            others = fitLine(otherX, otherY);
        } catch (const std::invalid_argument&) {
            continue;  // the others share one x: they say nothing about this point
        }
        const double offLine = std::abs(y[i] - (others.intercept + others.slope * x[i])) / span;
        if (!result.farthest || offLine > result.farthest->offLine) result.farthest = OffLinePoint{i, offLine};
    }
    result.pointOffLine = result.farthest && result.farthest->offLine > limits.maximumOffLine;
    return result;
}

}  // namespace tactiscope::core::calibration
