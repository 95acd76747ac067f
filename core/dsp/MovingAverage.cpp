// The moving average's ring and its exact re-summing.
#include "core/dsp/MovingAverage.h"

#include <algorithm>
#include <numeric>

namespace tactiscope::core::dsp {

MovingAverage::MovingAverage(std::size_t length)
    : m_window(std::max<std::size_t>(length, 1))
{
}

double MovingAverage::process(double x)
{
    const double n = static_cast<double>(m_window.size());
    if (!m_started) {
        std::fill(m_window.begin(), m_window.end(), x);
        m_sum = x * n;
        m_next = 0;
        m_started = true;
    }
    m_sum += x - m_window[m_next];
    m_window[m_next] = x;
    if (++m_next == m_window.size()) {
        m_next = 0;
        m_sum = std::accumulate(m_window.begin(), m_window.end(), 0.0);
    }
    return m_sum / n;
}

}  // namespace tactiscope::core::dsp
