// Watches a device's clock against the host's (ClockSync's fit, whose
// minimum-delay windows keep the transport's jitter out of it) and says
// when it drifts beyond kAlarm_ppm: the rate the device states is off by as
// much, and so is every time in its recording (a device that says 1000 Hz
// and samples at 1001 Hz is 3.6 s off in an hour). Said once, then at most
// every ten minutes of stream time. Gross mismatches (10 %) end the stream
// in BinaryStream; this is for the small lies.
#pragma once

#include "devices/ClockSync.h"

#include <optional>
#include <string>

namespace tactiscope::devices {

class DriftWatch {
public:
    // 500 ppm: ten times a cheap crystal's tolerance, and above what three
    // 5 s windows can measure (about ±70 ppm for 1 ms of delivery jitter).
    static constexpr double kAlarm_ppm = 500.0;
    static constexpr std::size_t kWindows = 3;
    static constexpr double kRepeat_s = 600.0;

    // The notice to give at this stream time, if any.
    std::optional<std::string> check(const ClockSync& clock, double streamTime_s);

private:
    std::optional<double> m_lastNotice_s;
};

}  // namespace tactiscope::devices
