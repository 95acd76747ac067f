// Least-squares line fits with centred sums (stable for offset data).
#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace tactiscope::core::calibration {
namespace {

void check(std::span<const double> x, std::span<const double> y)
{
    if (x.size() != y.size()) throw std::invalid_argument("fit: x and y differ in length");
    if (x.size() < 2) throw std::invalid_argument("fit: at least two points are needed");
}

void finish(LinearFit& fit, std::span<const double> x, std::span<const double> y, double sxx, std::size_t parameters)
{
    const auto n = static_cast<double>(x.size());
    const double meanY = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double ssResidual = 0.0, ssTotal = 0.0;
    fit.residuals.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        fit.residuals[i] = y[i] - (fit.intercept + fit.slope * x[i]);
        ssResidual += fit.residuals[i] * fit.residuals[i];
        ssTotal += (y[i] - meanY) * (y[i] - meanY);
    }
    fit.points = x.size();
    fit.rSquared = ssTotal > 0.0 ? 1.0 - ssResidual / ssTotal : 1.0;
    const double dof = n - static_cast<double>(parameters);
    if (dof > 0.0) {
        const double s2 = ssResidual / dof;
        fit.residualStandardDeviation = std::sqrt(s2);
        fit.slopeStandardError = std::sqrt(s2 / sxx);
        if (parameters == 2) {
            const double meanX = std::accumulate(x.begin(), x.end(), 0.0) / n;
            fit.interceptStandardError = std::sqrt(s2 * (1.0 / n + meanX * meanX / sxx));
        }
    }
}

}  // namespace

LinearFit fitLine(std::span<const double> x, std::span<const double> y)
{
    check(x, y);
    const auto n = static_cast<double>(x.size());
    const double meanX = std::accumulate(x.begin(), x.end(), 0.0) / n;
    const double meanY = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxx += (x[i] - meanX) * (x[i] - meanX);
        sxy += (x[i] - meanX) * (y[i] - meanY);
    }
    if (!(sxx > 0.0)) throw std::invalid_argument("fit: all x values are equal");
    LinearFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = meanY - fit.slope * meanX;
    finish(fit, x, y, sxx, 2);
    return fit;
}

LinearFit fitLineWithUncertainties(std::span<const double> x, std::span<const double> y, std::span<const double> u)
{
    check(x, y);
    if (u.size() != x.size()) throw std::invalid_argument("fit: every point needs its uncertainty");
    double sw = 0.0, swx = 0.0, swy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(u[i] > 0.0) || !std::isfinite(u[i])) throw std::invalid_argument("fit: uncertainties must be positive");
        const double w = 1.0 / (u[i] * u[i]);
        sw += w;
        swx += w * x[i];
        swy += w * y[i];
    }
    const double meanX = swx / sw, meanY = swy / sw;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double w = 1.0 / (u[i] * u[i]);
        sxx += w * (x[i] - meanX) * (x[i] - meanX);
        sxy += w * (x[i] - meanX) * (y[i] - meanY);
    }
    if (!(sxx > 0.0)) throw std::invalid_argument("fit: all x values are equal");
    LinearFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = meanY - fit.slope * meanX;
    finish(fit, x, y, sxx, 2);  // the unweighted residual σ and R², for display
    double chiSquare = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) chiSquare += fit.residuals[i] * fit.residuals[i] / (u[i] * u[i]);
    const double dof = static_cast<double>(x.size()) - 2.0;
    fit.birgeRatio = dof > 0.0 ? std::sqrt(chiSquare / dof) : 1.0;
    const double scale = std::max(1.0, fit.birgeRatio);
    fit.slopeStandardError = scale * std::sqrt(1.0 / sxx);
    fit.interceptStandardError = scale * std::sqrt(1.0 / sw + meanX * meanX / sxx);
    return fit;
}

LinearFit fitProportional(std::span<const double> x, std::span<const double> y)
{
    check(x, y);
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    if (!(sxx > 0.0)) throw std::invalid_argument("fit: all x values are zero");
    LinearFit fit;
    fit.slope = sxy / sxx;
    finish(fit, x, y, sxx, 1);
    return fit;
}

}  // namespace tactiscope::core::calibration
