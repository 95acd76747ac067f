// Watches a device's clock against the host's (core/timing/ClockAlignment:
// the lower hull of its blocks' arrivals keeps the transport's jitter out
// of it) and says when it drifts beyond kAlarm_ppm: the rate the device
// states is off by as much, and so is every time in its recording (a
// device that says 1000 Hz and samples at 1001 Hz is 3.6 s off in an
// hour). Said once the mapping spans kMinSpan_s, then at most every ten
// minutes of stream time. Gross mismatches (10 %) end the stream in
// BinaryStream; this is for the small lies.
#pragma once

#include "core/timing/ClockAlignment.h"

#include <optional>
#include <string>

namespace tactiscope::devices {

class DriftWatch {
public:
    // Whose rate is watched: a device's clock, or the rate a text board's
    // lines were timed at when they began (protocol/LineRate.h).
    enum class Subject { DeviceClock, TextLines };
    explicit DriftWatch(Subject subject = Subject::DeviceClock)
        : m_subject(subject)
    {
    }

    // 500 ppm: ten times a cheap crystal's tolerance, and far above what
    // 15 s of arrivals can mismeasure (a few ppm for 1–6 ms of delivery
    // jitter: core/timing).
    static constexpr double kAlarm_ppm = 500.0;
    static constexpr double kMinSpan_s = 15.0;
    static constexpr double kRepeat_s = 600.0;
    // The mapping is looked at once a second of stream time: it is fitted
    // anew each time (core/timing), and a drift needs no faster watch.
    static constexpr double kCheckEvery_s = 1.0;

    // The notice to give at this stream time, if any.
    std::optional<std::string> check(const core::timing::ClockAlignment& clock, double streamTime_s);

private:
    Subject m_subject;
    std::optional<double> m_lastNotice_s;
    std::optional<double> m_lastCheck_s;
};

}  // namespace tactiscope::devices
