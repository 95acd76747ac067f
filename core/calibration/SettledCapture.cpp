// SettledCapture: stable once, then a fresh stable window is the reading.
#include "core/calibration/SettledCapture.h"

#include <stdexcept>

namespace tactiscope::core::calibration {

SettledCapture::SettledCapture(StabilitySettings settings)
    : m_monitor(settings)
{
}

std::optional<WindowStatistics> SettledCapture::judge()
{
    m_latest = m_monitor.statistics();
    if (!m_latest || m_phase == Phase::Watching) return std::nullopt;
    if (m_phase == Phase::Averaging) {
        if (m_latest->stable) {
            m_phase = Phase::Watching;
            return m_latest;
        }
        // It moved again (a knock, a swinging weight): settle anew, keeping
        // the window so far, which shows when it is quiet again.
        m_phase = Phase::Settling;
        return std::nullopt;
    }
    if (m_latest->stable) {
        m_phase = Phase::Averaging;
        m_monitor.reset();
        m_latest.reset();
    }
    return std::nullopt;
}

void SettledCapture::arm()
{
    restart();
    m_phase = Phase::Settling;
}

std::optional<std::size_t> settledFrom(std::span<const double> t_s, std::span<const double> values,
                                       const StabilitySettings& settings)
{
    if (t_s.size() != values.size()) throw std::invalid_argument("times and values differ in length");
    SettledCapture capture(settings);
    capture.arm();
    for (std::size_t i = 0; i < t_s.size(); ++i) {
        capture.add(t_s[i], values[i]);
        // The kept window holds the samples added since the capture last reset.
        if (const auto kept = capture.judge()) return i + 1 - kept->count;
    }
    return std::nullopt;
}

void SettledCapture::restart()
{
    m_monitor.reset();
    m_latest.reset();
}

}  // namespace tactiscope::core::calibration
