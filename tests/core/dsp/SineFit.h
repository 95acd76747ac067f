// Test helper: the amplitude and phase of sines of known frequencies in a
// series, by least squares on sin and cos of each (plus a constant), so a
// filter's effect is measured in the time domain, independently of the
// responses the code under test computes.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace tactiscope::testing {

struct SineComponent {
    double amplitude = 0.0;
    double phase = 0.0;  // of sin(2π f t + phase)
};

inline std::vector<SineComponent> fitSines(std::span<const double> values, double rate_hz,
                                           const std::vector<double>& frequencies, std::size_t first = 0)
{
    const auto n = static_cast<Eigen::Index>(values.size() - first);
    const auto m = static_cast<Eigen::Index>(frequencies.size());
    Eigen::MatrixXd a(n, 2 * m + 1);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double t = static_cast<double>(first + static_cast<std::size_t>(i)) / rate_hz;
        for (Eigen::Index k = 0; k < m; ++k) {
            const double phase = 2.0 * std::numbers::pi * frequencies[static_cast<std::size_t>(k)] * t;
            a(i, 2 * k) = std::sin(phase);
            a(i, 2 * k + 1) = std::cos(phase);
        }
        a(i, 2 * m) = 1.0;
        y(i) = values[first + static_cast<std::size_t>(i)];
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(y);
    std::vector<SineComponent> result;
    for (Eigen::Index k = 0; k < m; ++k)
        result.push_back({std::hypot(c(2 * k), c(2 * k + 1)), std::atan2(c(2 * k + 1), c(2 * k))});
    return result;
}

}  // namespace tactiscope::testing
