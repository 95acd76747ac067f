// A device's clock mapped onto the host's steady clock (issue 40: several
// probes in one session on one clock). Each frame brings a pair: the time
// the device stamped on it and the time it arrived. Arrival is the
// device's instant, mapped, plus a delivery delay that is never negative
// and is often far above its minimum (the OS, USB polling, a busy core).
//
// Two steps, both resting on the frames that came through fastest, so
// however wild the jitter, it cannot bias the line:
//  1. The lower convex hull of the pairs, its edge over their mean device
//     time (Moon, Skelly and Towsley, "Estimation and removal of clock skew
//     from network delay measurements", INFOCOM 1999): a line under every
//     pair, robust to any delivery, even a regular one.
//  2. With enough frames, a stated uncertainty. The span is cut into ten
//     segments; in each, the fastest frame lies above the floor by an
//     amount whose scale is the gap between the next fastest ones (where
//     delays have a density at their floor, the fastest of n lie above it
//     by about 1/(n·density), and so do the gaps between them). Each
//     segment's fastest, lowered by that expected lift, is an unbiased
//     point on the floor with a known spread; a least-squares line through
//     the twenty gives the mapping and its standard uncertainty.
//  3. When those points scatter far more than their spread allows, or
//     their line passes above frames that came faster (a delivery locked
//     to a poll; a link whose rare frames are far faster than the rest, as
//     a pty's), the floor is not sharp: the hull's line stands, and the
//     uncertainty is a bound, the two lines' difference taken as the
//     half-width of a uniform distribution (a GUM type B evaluation).
//
// Frames held up at the start of the window (a port's backlog read at
// once, a board catching up on lines it could not send while nobody read)
// are set aside first: with nothing earlier to hold the floor down, their
// lags, falling a period per period, would tilt the hull's line.
//
// What it gives is the arrival floor: the device's instant plus the
// link's minimum delay, which no arrival can tell apart from the offset.
// Two devices on like links (the same kind of port) are aligned to within
// the stated uncertainty; a constant difference in minimum delay between
// unlike links remains (docs/multi-device.md).
//
// Bounded over hours: pairs are kept as the four fastest per quarter
// second of device time (with the count of all), over the last ten
// minutes, so drift that wanders with temperature is followed.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <optional>

namespace tactiscope::core::timing {

// How a mapping's uncertainty was found, or why it has none.
enum class ClockUncertaintyBasis {
    Spread,        // from the spread of the fastest frames' delays (a standard uncertainty)
    Bound,         // the floor is not sharp: half the gap between the fastest frames and the rest's floor
    TooFewFrames,  // fewer than kClockSegments × kClockFramesPerSegment frames in the window: none
    Exact,         // the source times its samples by the host's clock itself (the simulator): 0
};

// In words, for a report: "from the spread of …", "too few frames yet".
const char* describe(ClockUncertaintyBasis basis);

// host_s = device_s + offset_s + drift·(device_s − reference_s).
struct ClockMapping {
    double reference_s = 0.0;  // device time the offset is given at
    double offset_s = 0.0;     // host − device there
    double drift = 0.0;        // host seconds per device second, less one (+80e-6: the device is 80 ppm slow)
    double span_s = 0.0;       // device time the pairs it rests on cover
    std::size_t pairs = 0;
    // Standard uncertainties of the offset (at reference_s) and of the
    // drift; zero when there are too few frames.
    ClockUncertaintyBasis basis = ClockUncertaintyBasis::TooFewFrames;
    double offset_u_s = 0.0;
    double drift_u = 0.0;
    // The device's sample period. Where within it a sample's instant lies
    // (an ADC that integrates over the period or converts at its end, a
    // board that reads before or after it prints) no arrival tells: until
    // a common mark has calibrated it, a uniform doubt one period wide, a
    // standard uncertainty of T/√12 in every host time (GUM type B). Zero
    // for a source that times its samples by the host's clock.
    double samplePeriod_s = 0.0;

    double host_s(double device_s) const { return device_s + offset_s + drift * (device_s - reference_s); }
    // The inverse: the device time of a host instant.
    double device_s(double host_s) const { return (host_s - offset_s + drift * reference_s) / (1.0 + drift); }
    // The standard uncertainty of host_s(device_s), the sample period's
    // doubt included; none on too few frames.
    std::optional<double> uncertainty_s(double device_s) const;
    // Of it, the sample period's part: T/√12.
    double samplePeriodUncertainty_s() const;
};

// How well two devices' mapped times agree between the host instants
// `from_s` and `to_s`: the two mappings' standard uncertainties combined
// (they were estimated apart), at their largest there — a mapping's grows
// away from its middle, so at one of the ends. None when either states
// none.
std::optional<double> relativeUncertainty_s(const ClockMapping& a, const ClockMapping& b, double from_s, double to_s);

inline constexpr double kClockBin_s = 0.25;
inline constexpr double kClockWindow_s = 600.0;
inline constexpr std::size_t kClockSegments = 20;
inline constexpr std::size_t kClockFramesPerSegment = 20;

class ClockAlignment {
public:
    // `expectedDrift`: a device axis known to run off the host's clock
    // (one stretched on purpose); frames are held up against it.
    explicit ClockAlignment(double expectedDrift = 0.0)
        : m_expectedDrift(expectedDrift)
    {
    }

    // One frame's device stamp and host arrival, in seconds; the device's
    // stamps increase (a restart is a new ClockAlignment). Non-finite
    // values are ignored.
    void add(double device_s, double arrival_s);

    // None before pairs in two quarter seconds.
    std::optional<ClockMapping> mapping() const;

    std::size_t pairsSeen() const { return m_pairs; }
    std::size_t pointsKept() const;

    struct Point {
        double device_s;
        double lag_s;  // arrival − device
    };
    static constexpr std::size_t kKeptPerBin = 4;  // the fastest and three gaps above it
    struct Bin {
        long long index;
        std::size_t frames = 0;
        std::size_t kept = 0;
        std::array<Point, kKeptPerBin> fastest{};  // by lag, ascending
    };

private:
    std::deque<Bin> m_bins;
    std::size_t m_pairs = 0;
    double m_expectedDrift = 0.0;
};

}  // namespace tactiscope::core::timing
