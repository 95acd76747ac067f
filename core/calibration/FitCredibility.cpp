// FitCredibility: point count, R², leave-one-out distance from the line.
#include "core/calibration/FitCredibility.h"

#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
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
    // The suspect is the point least likely under the others' line: its
    // distance over the prediction error there, which grows with the
    // scatter of the others and with the distance from their centre (an end
    // point always sits far from a line fitted without it).
    double worstScore = -1.0;
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
        const double distance = std::abs(y[i] - (others.intercept + others.slope * x[i]));
        const auto n = static_cast<double>(otherX.size());
        const double meanX = std::accumulate(otherX.begin(), otherX.end(), 0.0) / n;
        double sxx = 0.0;
        for (double v : otherX) sxx += (v - meanX) * (v - meanX);
        const double predictionError =
            others.residualStandardDeviation * std::sqrt(1.0 + 1.0 / n + (x[i] - meanX) * (x[i] - meanX) / sxx);
        const double score = predictionError > 0.0 ? distance / predictionError
                             : distance > 0.0      ? std::numeric_limits<double>::infinity()
                                                   : 0.0;
        if (score > worstScore) {
            worstScore = score;
            result.farthest = OffLinePoint{i, distance / span};
        }
    }
    result.pointOffLine = result.farthest && result.farthest->offLine > limits.maximumOffLine;
    return result;
}

std::vector<double> residualsOfSpan(std::span<const double> residuals, std::span<const double> y)
{
    if (residuals.size() != y.size()) throw std::invalid_argument("residuals of span: one residual per point");
    if (y.empty()) return {};
    const auto [low, high] = std::minmax_element(y.begin(), y.end());
    const double span = *high - *low;
    if (!(span > 0.0)) return {};
    std::vector<double> fractions;
    fractions.reserve(residuals.size());
    for (double r : residuals) fractions.push_back(r / span);
    return fractions;
}

}  // namespace tactiscope::core::calibration
