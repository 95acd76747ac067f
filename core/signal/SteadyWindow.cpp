// SteadyWindow: the sums are recomputed on demand; a tare asks rarely.
#include "core/signal/SteadyWindow.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace tactiscope::core::signal {
namespace {

struct HalfStatistics {
    double mean = 0.0;
    double sumSquares = 0.0;  // of deviations from the mean
    std::size_t count = 0;
};

template <typename Iterator>
HalfStatistics statisticsOf(Iterator first, Iterator last)
{
    HalfStatistics s;
    s.count = static_cast<std::size_t>(std::distance(first, last));
    for (auto it = first; it != last; ++it) s.mean += *it;
    s.mean /= static_cast<double>(s.count);
    for (auto it = first; it != last; ++it) s.sumSquares += (*it - s.mean) * (*it - s.mean);
    return s;
}

}  // namespace

SteadyWindow::SteadyWindow(std::size_t length)
    : m_length(length)
{
    if (length < 4) throw std::invalid_argument("a steadiness window needs at least 4 samples");
}

void SteadyWindow::push(double value)
{
    if (m_values.size() == m_length) m_values.pop_front();
    m_values.push_back(value);
}

double SteadyWindow::mean() const
{
    if (m_values.empty()) return 0.0;
    double sum = 0.0;
    for (const double v : m_values) sum += v;
    return sum / static_cast<double>(m_values.size());
}

double SteadyWindow::spread() const
{
    if (m_values.empty()) return 0.0;
    const auto [low, high] = std::ranges::minmax_element(m_values);
    return *high - *low;
}

double SteadyWindow::standardErrorOfMean() const
{
    if (m_values.size() < 2) return 0.0;
    const HalfStatistics all = statisticsOf(m_values.begin(), m_values.end());
    const auto n = static_cast<double>(all.count);
    return std::sqrt(all.sumSquares / (n - 1.0) / n);
}

double SteadyWindow::halfShift() const
{
    if (m_values.size() < 4) return 0.0;
    const auto middle = m_values.begin() + static_cast<std::ptrdiff_t>(m_values.size() / 2);
    return statisticsOf(middle, m_values.end()).mean - statisticsOf(m_values.begin(), middle).mean;
}

double SteadyWindow::halfShiftScore() const
{
    if (m_values.size() < 4) return 0.0;
    const auto middle = m_values.begin() + static_cast<std::ptrdiff_t>(m_values.size() / 2);
    const HalfStatistics first = statisticsOf(m_values.begin(), middle);
    const HalfStatistics second = statisticsOf(middle, m_values.end());
    const double shift = std::abs(second.mean - first.mean);
    // Pooled variance within the halves, then the standard error of the
    // difference of two means.
    const double variance =
        (first.sumSquares + second.sumSquares) / static_cast<double>(first.count + second.count - 2);
    const double standardError =
        std::sqrt(variance * (1.0 / static_cast<double>(first.count) + 1.0 / static_cast<double>(second.count)));
    if (standardError == 0.0) return shift == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return shift / standardError;
}

double SteadyWindow::stepScore() const
{
    const std::size_t n = m_values.size();
    if (n < 4) return 0.0;
    // Sums and sums of squares of the first i values, about the first (so
    // that a large level costs no precision).
    std::vector<double> sums(n + 1, 0.0), squares(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double v = m_values[i] - m_values.front();
        sums[i + 1] = sums[i] + v;
        squares[i + 1] = squares[i] + v * v;
    }
    double largest = 0.0;
    for (std::size_t k = 1; k < n; ++k) {
        const auto before = static_cast<double>(k), after = static_cast<double>(n - k);
        const double meanBefore = sums[k] / before, meanAfter = (sums[n] - sums[k]) / after;
        const double shift = std::abs(meanAfter - meanBefore);
        if (shift == 0.0) continue;
        const double within = std::max(0.0, squares[k] - before * meanBefore * meanBefore) +
                              std::max(0.0, squares[n] - squares[k] - after * meanAfter * meanAfter);
        const double standardError = std::sqrt(within / static_cast<double>(n - 2) * (1.0 / before + 1.0 / after));
        if (!(standardError > 1e-12 * shift)) return std::numeric_limits<double>::infinity();
        largest = std::max(largest, shift / standardError);
    }
    return largest;
}

}  // namespace tactiscope::core::signal
