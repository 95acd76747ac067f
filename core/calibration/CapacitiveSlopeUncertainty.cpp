// CapacitiveSlopeUncertainty: the steps' covariance, the slope's variance
// through the least-squares weights, and the χ² check of the residuals.
#include "core/calibration/CapacitiveSlopeUncertainty.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::calibration {
namespace {

using Matrix = std::vector<std::vector<double>>;

// Where the step lies between the two baselines, 0 at the first and 1 at
// the final (0 throughout without a final one: no drift is removed).
double fractionBetween(const SlopeUncertaintyInput& in, double t_s)
{
    if (!in.final || !(in.final->t_s > in.first.t_s)) return 0.0;
    return std::clamp((t_s - in.first.t_s) / (in.final->t_s - in.first.t_s), 0.0, 1.0);
}

Matrix covariance(const SlopeUncertaintyInput& in)
{
    const std::size_t n = in.steps.size();
    const double wander2 = in.wander_f_per_sqrt_s ? *in.wander_f_per_sqrt_s * *in.wander_f_per_sqrt_s : 0.0;
    const double u0 = in.first.u_f, uf = in.final ? in.final->u_f : 0.0;
    Matrix v(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double pi = fractionBetween(in, in.steps[i].t_s);
        for (std::size_t j = 0; j < n; ++j) {
            const double pj = fractionBetween(in, in.steps[j].t_s);
            double vij = u0 * u0 * (1.0 - pi) * (1.0 - pj) + uf * uf * pi * pj;
            // The random walk since the first baseline, tied down at the
            // final one when there is one (a Brownian bridge).
            const double early = std::min(in.steps[i].t_s, in.steps[j].t_s) - in.first.t_s;
            const double late = std::max(in.steps[i].t_s, in.steps[j].t_s) - in.first.t_s;
            if (in.final && in.final->t_s > in.first.t_s) {
                const double span = in.final->t_s - in.first.t_s;
                vij += wander2 * std::max(0.0, early) * std::max(0.0, span - late) / span;
            } else {
                vij += wander2 * std::max(0.0, early);
            }
            if (i == j) vij += in.steps[i].u_f * in.steps[i].u_f;
            v[i][j] = vij;
        }
    }
    return v;
}

// rᵀ·V⁻¹·r by Cholesky (V is positive definite: every step has noise).
std::optional<double> chiSquare(Matrix v, const std::vector<double>& r)
{
    const std::size_t n = r.size();
    for (std::size_t j = 0; j < n; ++j) {
        double d = v[j][j];
        for (std::size_t k = 0; k < j; ++k) d -= v[j][k] * v[j][k];
        if (!(d > 0.0)) return std::nullopt;
        v[j][j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < n; ++i) {
            double s = v[i][j];
            for (std::size_t k = 0; k < j; ++k) s -= v[i][k] * v[j][k];
            v[i][j] = s / v[j][j];
        }
    }
    std::vector<double> z(n);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        double s = r[i];
        for (std::size_t k = 0; k < i; ++k) s -= v[i][k] * z[k];
        z[i] = s / v[i][i];
        sum += z[i] * z[i];
    }
    return sum;
}

// The 99th percentile of χ² with `degrees` degrees of freedom, per degree
// (Wilson and Hilferty's cube-root normal approximation).
double chiSquare99PerDegree(double degrees)
{
    const double a = 2.0 / (9.0 * degrees);
    return std::pow(1.0 - a + 2.3263 * std::sqrt(a), 3.0);
}

}  // namespace

std::optional<SlopeUncertainty> propagatedSlopeUncertainty(const SlopeUncertaintyInput& in)
{
    const std::size_t n = in.steps.size();
    if (n < 2 || std::ranges::any_of(in.steps, [](const SlopePoint& p) { return !(p.u_f > 0.0); })) return std::nullopt;
    // The least-squares slope's weights over the steps, the zero point
    // (force 0, ΔC 0 by definition) among the fitted points.
    double mean = 0.0;
    for (const auto& p : in.steps) mean += p.force_n;
    mean /= static_cast<double>(n + 1);
    double sxx = mean * mean;
    for (const auto& p : in.steps) sxx += (p.force_n - mean) * (p.force_n - mean);
    const Matrix v = covariance(in);
    double variance = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            variance += (in.steps[i].force_n - mean) * (in.steps[j].force_n - mean) * v[i][j] / (sxx * sxx);
    SlopeUncertainty out;
    out.u_f_per_n = std::sqrt(variance);
    std::vector<double> residuals;
    for (const auto& p : in.steps) residuals.push_back(p.residual_f);
    // The n + 1 points less the line's two parameters.
    const auto degrees = static_cast<double>(n - 1);
    if (const auto chi2 = chiSquare(v, residuals)) {
        out.chiSquarePerDegree = *chi2 / degrees;
        if (out.chiSquarePerDegree > chiSquare99PerDegree(degrees)) {
            out.widened = true;
            out.u_f_per_n *= std::sqrt(out.chiSquarePerDegree);
        }
    }
    return out;
}

}  // namespace tactiscope::core::calibration
