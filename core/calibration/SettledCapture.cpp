// SettledCapture: stable once, then a fresh stable window is the reading.
#include "core/calibration/SettledCapture.h"

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

void SettledCapture::restart()
{
    m_monitor.reset();
    m_latest.reset();
}

}  // namespace tactiscope::core::calibration
