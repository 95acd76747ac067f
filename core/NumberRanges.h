// The ranges the numbers a user, a device or a file gives are held to, in
// one place (docs/user-guide.md, "Numbers and their ranges"): the CLI's
// options, a limit's hold, a stored channel's rate. Each bound says why it
// is where it is; a value outside is refused with the range, never taken
// to grow a buffer without bound (before, `--pre 1e9` grew the pre-trigger
// buffer by 1.34 MB/s at 16 channels × 10 kHz, and `shunt-check
// --tolerance 1e300` passed a quarter bridge read as a full one).
#pragma once

#include <cmath>
#include <string>

namespace tactiscope::core {

struct NumberRange {
    double least = 0.0;
    double most = 0.0;
    const char* unit = "";  // as shown after the numbers ("s", "Hz", "%")

    bool holds(double value) const { return std::isfinite(value) && value >= least && value <= most; }
    // "from 0 to 60 s"
    std::string text() const;
};

// A sample rate: one sample in 11.6 days up to the central store's bound
// on a channel (CentralSchema: sample_rate_hz <= 1e9).
inline constexpr NumberRange kSampleRateRange{1e-6, 1e9, "Hz"};
// A recording's set length: a millisecond to 31 days (longer runs until
// stopped, without --seconds).
inline constexpr NumberRange kRecordingSecondsRange{0.001, 2678400.0, "s"};
// Triggered sessions to record (--rearm records without end).
inline constexpr NumberRange kTriggeredSessionsRange{1.0, 1e6, ""};
// Seconds a trigger keeps before it: the buffer holds that long of every
// channel, 77 MB at 16 channels × 10 kHz for 60 s.
inline constexpr NumberRange kPreTriggerRange{0.0, 60.0, "s"};
// Seconds a triggered session goes on after its condition, and waits
// before the next: an hour, a day (longer is a recording by hand).
inline constexpr NumberRange kPostTriggerRange{0.0, 3600.0, "s"};
inline constexpr NumberRange kHoldOffRange{0.0, 86400.0, "s"};
// How long a quantity stays beyond a limit before the alarm is raised.
inline constexpr NumberRange kLimitHoldRange{0.0, 3600.0, "s"};
// A shunt check's tolerance: a quarter bridge read as a full one is off by
// a factor of four (−75 %, +300 %), so a tolerance must stay well inside.
inline constexpr NumberRange kShuntToleranceRange{0.01, 50.0, "%"};
// A shunt check's resistors and gauge factor: what gauges and shunts are.
inline constexpr NumberRange kGaugeOhmsRange{1.0, 1e5, "Ω"};
inline constexpr NumberRange kShuntOhmsRange{1.0, 1e9, "Ω"};
inline constexpr NumberRange kGaugeFactorRange{0.1, 200.0, ""};
// A spectrum's averages: one segment (the finest resolution) to a hundred
// thousand (an hour at 10 kHz in 64-sample segments, the shortest).
inline constexpr NumberRange kSpectrumAveragesRange{1.0, 1e5, ""};
// A Butterworth filter's cut-off (the sample rate's range; the filter then
// asks for below 0.45 of the channel's rate) and order: 2 to 8, where
// a 8th order already falls 48 dB per octave.
inline constexpr NumberRange kFilterCutoffRange{1e-6, 1e9, "Hz"};
inline constexpr NumberRange kFilterOrderRange{2.0, 8.0, ""};
// A moving average's window: up to a minute (longer is a drift analysis).
inline constexpr NumberRange kMovingAverageRange{0.0, 60.0, "s"};

}  // namespace tactiscope::core
