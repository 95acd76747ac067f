// RateMeter: windowed sample-rate estimate.
#include "core/RateMeter.h"

#include <stdexcept>

namespace tactiscope::core {

RateMeter::RateMeter(double window_s)
    : m_window_s(window_s)
{
    if (!(window_s > 0.0)) throw std::invalid_argument("RateMeter window must be positive");
}

void RateMeter::observe(double now_s, std::uint64_t totalSamples)
{
    if (!m_started) {
        m_started = true;
        m_windowStart_s = now_s;
        m_windowStartCount = totalSamples;
        return;
    }
    const double elapsed_s = now_s - m_windowStart_s;
    if (elapsed_s < m_window_s) return;
    m_rate_hz = static_cast<double>(totalSamples - m_windowStartCount) / elapsed_s;
    m_windowStart_s = now_s;
    m_windowStartCount = totalSamples;
}

void RateMeter::reset()
{
    m_started = false;
    m_rate_hz.reset();
}

}  // namespace tactiscope::core
