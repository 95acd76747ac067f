// Sliding-window drift and noise test.
#include "core/calibration/StabilityMonitor.h"

#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tactiscope::core::calibration {

StabilityMonitor::StabilityMonitor(StabilitySettings settings)
    : m_settings(settings)
{
    if (!(settings.window_s > 0.0)) throw std::invalid_argument("stability window must be positive");
    if (!(settings.maxDrift_per_s >= 0.0) || !(settings.maxNoise >= 0.0))
        throw std::invalid_argument("stability limits must not be negative");
}

void StabilityMonitor::add(double t_s, double value)
{
    m_samples.emplace_back(t_s, value);
    while (m_samples.size() > 2 && t_s - m_samples[1].first >= m_settings.window_s) m_samples.pop_front();
}

std::optional<WindowStatistics> StabilityMonitor::push(double t_s, double value)
{
    add(t_s, value);
    return statistics();
}

std::optional<WindowStatistics> StabilityMonitor::statistics() const
{
    if (m_samples.size() < 3 || m_samples.back().first - m_samples.front().first < m_settings.window_s)
        return std::nullopt;

    std::vector<double> t, v;
    for (const auto& [time, x] : m_samples) {
        t.push_back(time);
        v.push_back(x);
    }
    const LinearFit line = fitLine(t, v);
    WindowStatistics w;
    double sum = 0.0;
    for (double x : v) sum += x;
    w.mean = sum / static_cast<double>(v.size());
    w.sigma = line.residualStandardDeviation;
    w.meanStandardError = meanStandardError(line.residuals);
    w.drift_per_s = line.slope;
    w.start_s = t.front();
    w.end_s = t.back();
    w.count = v.size();
    w.stable = std::abs(w.drift_per_s) <= m_settings.maxDrift_per_s && w.sigma <= m_settings.maxNoise;
    return w;
}

double meanStandardError(std::span<const double> residuals)
{
    const std::size_t n = residuals.size();
    if (n < 3) return 0.0;
    double squares = 0.0, neighbours = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        squares += residuals[i] * residuals[i];
        if (i + 1 < n) neighbours += residuals[i] * residuals[i + 1];
    }
    if (!(squares > 0.0)) return 0.0;
    const double rho = std::clamp(neighbours / squares, 0.0, 0.95);
    const double sigma = std::sqrt(squares / static_cast<double>(n - 2));  // a line's two parameters fitted
    return sigma / std::sqrt(static_cast<double>(n)) * std::sqrt((1.0 + rho) / (1.0 - rho));
}

std::optional<WindowStatistics> firstStableWindow(std::span<const double> t, std::span<const double> values,
                                                  const StabilitySettings& settings, std::size_t from)
{
    if (t.size() != values.size()) throw std::invalid_argument("times and values differ in length");
    StabilityMonitor monitor(settings);
    for (std::size_t i = from; i < t.size(); ++i) {
        if (auto w = monitor.push(t[i], values[i]); w && w->stable) return w;
    }
    return std::nullopt;
}

}  // namespace tactiscope::core::calibration
