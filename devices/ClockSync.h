// Maps a device's clock onto the host's, correcting the drift between the
// two crystals (typically tens of ppm, i.e. milliseconds per minute).
//
// Method (minimum-delay regression): each block gives a pair (device time of
// its last sample, host time it arrived). The transport only ever adds
// delay, so within each 5 s window the pair with the smallest
// (host − device) difference is the least delayed; a least-squares line
// through the last 12 windows' minima (one minute) gives the offset and the
// drift, and host = device + offset + drift·device. Until two windows exist
// the smallest difference seen so far is the offset.
#pragma once

#include <deque>
#include <optional>
#include <utility>

namespace tactiscope::devices {

class ClockSync {
public:
    static constexpr double kWindow_s = 5.0;
    static constexpr std::size_t kWindows = 12;

    void observe(double device_s, double hostArrival_s);
    // Host time of a device time; the device time itself before any observation.
    double hostTime_s(double device_s) const;
    // Relative drift (host − device rate), e.g. −1e-4 for a device 100 ppm fast.
    double drift() const { return m_drift; }
    // Windows the drift is fitted over (at most kWindows).
    std::size_t windows() const { return m_minima.size(); }
    void reset();

private:
    void refit();

    std::deque<std::pair<double, double>> m_minima;  // (device time, host − device) per window
    std::optional<std::pair<double, double>> m_current;
    double m_windowStart_s = 0.0;
    double m_offset_s = 0.0;
    double m_drift = 0.0;
    bool m_any = false;
};

}  // namespace tactiscope::devices
