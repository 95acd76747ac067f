// Minimum-delay regression of the device clock against the host's.
#include "devices/ClockSync.h"

namespace tactiscope::devices {

void ClockSync::reset()
{
    *this = ClockSync{};
}

void ClockSync::observe(double device_s, double hostArrival_s)
{
    const double difference = hostArrival_s - device_s;
    if (!m_current) {
        m_current.emplace(device_s, difference);
        m_windowStart_s = device_s;
    } else if (difference < m_current->second) {
        *m_current = {device_s, difference};
    }
    if (!m_any || m_minima.size() < 2) {
        // Not enough windows for a drift yet: the best offset so far.
        m_offset_s = m_any ? std::min(m_offset_s + 0.0, difference) : difference;
        m_any = true;
    }
    if (device_s - m_windowStart_s >= kWindow_s) {
        m_minima.push_back(*m_current);
        if (m_minima.size() > kWindows) m_minima.pop_front();
        m_current.reset();
        refit();
    }
}

void ClockSync::refit()
{
    if (m_minima.size() < 2) return;
    const auto n = static_cast<double>(m_minima.size());
    double mx = 0.0, my = 0.0;
    for (const auto& [x, y] : m_minima) {
        mx += x / n;
        my += y / n;
    }
    double sxx = 0.0, sxy = 0.0;
    for (const auto& [x, y] : m_minima) {
        sxx += (x - mx) * (x - mx);
        sxy += (x - mx) * (y - my);
    }
    m_drift = sxx > 0.0 ? sxy / sxx : 0.0;
    m_offset_s = my - m_drift * mx;
}

double ClockSync::hostTime_s(double device_s) const
{
    return device_s + m_offset_s + m_drift * device_s;
}

}  // namespace tactiscope::devices
