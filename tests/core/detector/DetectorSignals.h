// Test signals for the detector with known answers.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

namespace tactiscope::testing {

// White Gaussian noise of the given σ, reproducible by seed.
inline std::vector<double> whiteNoise(std::size_t n, double sigma, unsigned seed)
{
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal(0.0, sigma);
    std::vector<double> x(n);
    for (double& v : x) v = normal(random);
    return x;
}

// x delayed by k samples, zero before the start.
inline std::vector<double> delayedBy(const std::vector<double>& x, std::size_t k)
{
    std::vector<double> y(x.size(), 0.0);
    for (std::size_t i = k; i < x.size(); ++i) y[i] = x[i - k];
    return y;
}

inline std::vector<double> plus(std::vector<double> x, const std::vector<double>& y)
{
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
    return x;
}

// amplitude · sin(2π f t + phase) sampled every dt.
inline std::vector<double> sine(std::size_t n, double dt, double f, double amplitude, double phase = 0.0)
{
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i)
        x[i] = amplitude * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) * dt + phase);
    return x;
}

}  // namespace tactiscope::testing
