// DriftWatch: a device clock's drift against the host's, as an alarm.
#include "devices/DriftWatch.h"

#include <cmath>
#include <cstdio>

namespace tactiscope::devices {

std::optional<std::string> DriftWatch::check(const core::timing::ClockAlignment& alignment, double streamTime_s)
{
    if (m_lastCheck_s && streamTime_s >= *m_lastCheck_s && streamTime_s - *m_lastCheck_s < kCheckEvery_s)
        return std::nullopt;
    m_lastCheck_s = streamTime_s;
    const auto clock = alignment.mapping();
    if (!clock || clock->span_s < kMinSpan_s) return std::nullopt;
    // drift = d(host − device)/d(device): negative when the device's time
    // runs ahead of the host's, i.e. it samples faster than it says.
    const double ppm = -clock->drift * 1e6;
    if (std::abs(ppm) < kAlarm_ppm) return std::nullopt;
    if (m_lastNotice_s && streamTime_s - *m_lastNotice_s < kRepeat_s) return std::nullopt;
    m_lastNotice_s = streamTime_s;
    char text[256];
    if (m_subject == Subject::TextLines)
        std::snprintf(text, sizeof text,
                      "the board's lines now come %.0f ppm %s than the rate they were timed at when they began: "
                      "every time in the recording is off by as much (%.1f s an hour)",
                      std::abs(ppm), ppm > 0.0 ? "faster" : "slower", std::abs(ppm) * 1e-6 * 3600.0);
    else
        std::snprintf(text, sizeof text,
                      "the device's clock runs %.0f ppm %s against the host's: the rate it states is off by as much, "
                      "and so is every time in the recording (%.1f s an hour)",
                      std::abs(ppm), ppm > 0.0 ? "fast" : "slow", std::abs(ppm) * 1e-6 * 3600.0);
    return text;
}

}  // namespace tactiscope::devices
