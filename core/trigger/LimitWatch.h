// Limit alarms on one channel or derived quantity (issue 39): a warning and
// a critical level, or a window for each, beyond which the value must stay
// for a hold time to raise its alarm, and back by a hysteresis for a clear
// time (0.1 s) to clear it, so noise at a level does not chatter. The rules
// live below the UI: the CLI (`record --limit`) and the GUI share them.
//   force>warning:0.002,critical:0.003    above: 2 mN warns, 3 mN is critical
//   a<warning:-8e-4,critical:-1e-3         below
//   force>critical:0.003,hold:0.2          beyond it for 0.2 s before it is raised
//   a outside warning:-900..900,critical:-990..990   either way out of a window
//   C inside critical:-1e-15..1e-15        within a window (a dead channel)
// Above, below and outside are one rule: the value must stay within an
// allowed range, open at one end for above and below; inside forbids the
// range instead.
#pragma once

#include "core/ChannelDescriptor.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::trigger {

enum class LimitSeverity { Warning, Critical };
const char* toString(LimitSeverity severity);  // "warning", "critical"

enum class LimitSide { Above, Below, Inside, Outside };
const char* toString(LimitSide side);  // "above", "below", "inside", "outside"
bool isWindow(LimitSide side);         // inside or outside: its levels are LOW..HIGH

// One level: a number above or below, a window's ends inside or outside.
struct LimitLevel {
    double low = 0.0;
    double high = 0.0;  // the same as low above or below

    LimitLevel() = default;
    // Above or below, a level is one number.
    LimitLevel(double at)  // NOLINT(google-explicit-constructor)
        : low(at),
          high(at)
    {
    }
    LimitLevel(double lowEnd, double highEnd)
        : low(lowEnd),
          high(highEnd)
    {
    }
    bool operator==(const LimitLevel&) const = default;
};

struct LimitSpec {
    std::string quantity;
    LimitSide side = LimitSide::Above;
    std::optional<LimitLevel> warning, critical;
    // Back past a level by this much clears its alarm (a fraction of the
    // level's size, a window's larger end; by default 2 %) once it stays
    // back for clear_s; beyond it for hold_s raises it. The clear time
    // keeps noise spikes across a level from raising and clearing dozens of
    // times a second when the noise is larger than the hysteresis.
    double hysteresis_fraction = 0.02;
    double hold_s = 0.0;
    double clear_s = 0.1;

    const std::optional<LimitLevel>& level(LimitSeverity severity) const
    {
        return severity == LimitSeverity::Warning ? warning : critical;
    }
    std::string text() const;  // back in the form above
    // Whether a limit given on the same quantity takes this one's place:
    // they guard a side in common (outside guards both above and below).
    bool replaces(const LimitSpec& other) const;
};

struct ParsedLimit {
    std::optional<LimitSpec> limit;
    std::string error;
};
// "QUANTITY>warning:W,critical:C[,hold:S]" (or <), "QUANTITY outside
// warning:A..B,critical:C..D[,hold:S]" (or inside); either level may be
// left out, not both. The critical level lies beyond the warning one:
// above it, below it, a window around it outside, within it inside.
ParsedLimit parseLimit(std::string_view text);

// How an alarm's numbers read: the levels as they are typed, the measured
// value, both in `unit` (none: SI, as stored).
struct LimitWording {
    std::function<std::string(double)> level;     // the number, in `unit`
    std::function<std::string(double)> measured;  // the number and its unit
    std::string unit;
};

// The wording a stored alarm keeps, in the units people read it in: a
// strain in µε, another quantity in its SI unit with the prefix that puts
// `level` (the limit's) between 1 and 1000 (956 µN, 3 mN, 51.4 pF), the
// measured value to three digits in the same unit (in its own prefix when
// a thousandfold beyond); a quantity without a unit as it is.
LimitWording readableWording(ChannelKind kind, const std::string& unit, double level);

// A raised or cleared alarm: at sample `index`, the value then.
struct LimitChange {
    LimitSeverity severity = LimitSeverity::Warning;
    bool raised = true;
    std::uint64_t index = 0;
    double value = 0.0;

    // "force above its critical limit 0.003 N (0.0031 N)", "a outside its
    // warning window -900..900 count (912 count)", "force back below its
    // critical limit 0.003 N": in the quantity's SI unit, or worded.
    std::string text(const LimitSpec& spec, const std::string& unit = {}) const;
    std::string text(const LimitSpec& spec, const LimitWording& wording) const;
};

class LimitWatch {
public:
    // Throws std::invalid_argument for a rate that is not positive or a
    // hold time or hysteresis that is negative.
    LimitWatch(LimitSpec spec, double sampleRate_hz);

    // One sample's value (NaN, a lost sample, changes nothing); the alarms
    // raised or cleared at it, in `changes`.
    void push(std::uint64_t index, double value, std::vector<LimitChange>& changes);

    bool raised(LimitSeverity severity) const { return m_level[static_cast<int>(severity)].raised; }
    const LimitSpec& spec() const { return m_spec; }

private:
    // A level as the range the value must stay in (inside: must stay out
    // of), and the narrower range it must come back to.
    struct Level {
        bool watched = false;
        double low = 0.0, high = 0.0;
        double hysteresis = 0.0;
        bool raised = false;
        std::optional<std::uint64_t> beyondSince;  // first sample of the current run beyond the level
        std::optional<std::uint64_t> backSince;    // first sample of the current run back, raised
    };
    bool beyond(const Level& level, double value) const;
    bool back(const Level& level, double value) const;

    LimitSpec m_spec;
    std::uint64_t m_hold;
    std::uint64_t m_clear;
    Level m_level[2];
};

}  // namespace tactiscope::core::trigger
