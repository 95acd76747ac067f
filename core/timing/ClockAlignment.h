// A device's clock mapped onto the host's steady clock (issue 40: several
// probes in one session on one clock). Each frame brings a pair: the time
// the device stamped on it and the time it arrived. Arrival is the
// device's instant, mapped, plus a delivery delay that is never negative
// and is often far above its minimum (the OS, USB polling, a busy core):
// the mapping is the line under all the pairs that lies closest to them,
// the lower convex hull's edge over their mean device time (Moon, Skelly
// and Towsley, "Estimation and removal of clock skew from network delay
// measurements", INFOCOM 1999). Jitter only lifts points above the line,
// so however wild it is, the frames that came through fastest decide.
//
// What it gives is the arrival floor: the device's instant plus the
// link's minimum delay, which no arrival can tell apart from the offset.
// Two devices on like links (the same kind of port) are aligned to within
// the estimate's own error; a constant difference in minimum delay between
// unlike links remains (docs/multi-device.md).
//
// Bounded over hours: pairs are kept as the fastest per quarter second of
// device time (a later pair can only raise the others in it), over the
// last ten minutes, so drift that wanders with temperature is followed.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

namespace tactiscope::core::timing {

// host_s = device_s + offset_s + drift·(device_s − reference_s).
struct ClockMapping {
    double reference_s = 0.0;  // device time the offset is given at
    double offset_s = 0.0;     // host − device there
    double drift = 0.0;        // host seconds per device second, less one (+80e-6: the device is 80 ppm slow)
    double span_s = 0.0;       // device time the pairs it rests on cover
    std::size_t pairs = 0;

    double host_s(double device_s) const { return device_s + offset_s + drift * (device_s - reference_s); }
};

inline constexpr double kClockBin_s = 0.25;
inline constexpr double kClockWindow_s = 600.0;

class ClockAlignment {
public:
    // One frame's device stamp and host arrival, in seconds; the device's
    // stamps increase (a restart is a new ClockAlignment). Non-finite
    // values are ignored.
    void add(double device_s, double arrival_s);

    // None before pairs in two quarter seconds.
    std::optional<ClockMapping> mapping() const;

    std::size_t pairsSeen() const { return m_pairs; }
    std::size_t pointsKept() const { return m_points.size(); }

private:
    struct Point {
        double device_s;
        double lag_s;  // arrival − device
    };
    std::deque<Point> m_points;  // the fastest pair of each bin, in device time
    std::optional<long long> m_lastBin;
    std::size_t m_pairs = 0;
};

}  // namespace tactiscope::core::timing
