// The drift line through interval means and its standard error.
#include "core/dsp/DriftRate.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::dsp {
namespace {

constexpr std::uint64_t kIntervals = 100;

}  // namespace

std::uint64_t driftIntervalSamples(std::uint64_t samples)
{
    return std::max<std::uint64_t>(1, samples / kIntervals);
}

DriftAccumulator::DriftAccumulator(double sampleRate_hz, std::uint64_t intervalSamples)
    : m_rate_hz(sampleRate_hz),
      m_intervalSamples(std::max<std::uint64_t>(1, intervalSamples))
{
}

void DriftAccumulator::push(double value)
{
    if (std::isfinite(value)) {
        m_sum += value;
        m_indexSum += static_cast<double>(m_index);
        ++m_count;
    }
    ++m_index;
    if (++m_inInterval == m_intervalSamples) closeInterval();
}

void DriftAccumulator::closeInterval()
{
    // An interval mostly lost says little about its level: left out.
    if (2 * m_count >= m_intervalSamples && m_count > 0) {
        m_t.push_back(m_indexSum / static_cast<double>(m_count) / m_rate_hz);
        m_mean.push_back(m_sum / static_cast<double>(m_count));
    }
    m_sum = m_indexSum = 0.0;
    m_count = m_inInterval = 0;
}

std::optional<Drift> DriftAccumulator::result() const
{
    if (m_inInterval > 0) {  // the last interval, cut short by the end
        DriftAccumulator ended = *this;
        ended.closeInterval();
        return ended.result();
    }
    const std::size_t n = m_t.size();
    if (n < 3) return std::nullopt;
    double tMean = 0.0;
    double yMean = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        tMean += m_t[i];
        yMean += m_mean[i];
    }
    tMean /= static_cast<double>(n);
    yMean /= static_cast<double>(n);
    double stt = 0.0;
    double sty = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        stt += (m_t[i] - tMean) * (m_t[i] - tMean);
        sty += (m_t[i] - tMean) * (m_mean[i] - yMean);
    }
    if (!(stt > 0.0)) return std::nullopt;
    const double slope = sty / stt;
    double residuals = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = m_mean[i] - yMean - slope * (m_t[i] - tMean);
        residuals += r * r;
    }
    const double u = std::sqrt(residuals / static_cast<double>(n - 2) / stt);
    return Drift{slope, u, n};
}

}  // namespace tactiscope::core::dsp
