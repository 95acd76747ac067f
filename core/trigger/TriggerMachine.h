// When a triggered recording starts and ends, sample by sample, for the
// CLI's `record --trigger` and the GUI alike (the rules live here, below
// the UI). Indices are the stream's sample indices; the caller keeps the
// last pre-trigger samples in its live buffer, so a session reaches back
// before its trigger and nothing before the trigger is lost.
//
// States: Waiting (the condition still holds from before, or the hold-off
// after the last session runs), Armed (the next time the condition begins
// is a trigger), Triggered (a session is being cut: until `post` after the
// condition clears, or after an edge), Finished (the sessions asked for
// are done).
#pragma once

#include "core/trigger/TriggerCondition.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tactiscope::core::trigger {

struct TriggerSettings {
    TriggerCondition condition;
    double pre_s = 0.0;                // kept before the trigger instant
    double post_s = 0.0;               // kept after the condition clears (an edge: after it)
    double holdOff_s = 0.0;            // after a session ends, before the next may trigger
    std::optional<unsigned> sessions;  // how many, then Finished; none: re-arm for ever
};

// The settings as a session's record keeps them: "a>2e-05, pre 0.5 s,
// post 1 s, hold-off 0 s".
std::string settingsText(const TriggerSettings& settings);

// The subject of the `n`th session (from 0) a trigger cuts, numbered on
// from the first's: door-17, door-18, …; panel-009, panel-010 (the digits'
// width kept); a subject without a number: panel, panel-2, panel-3; none
// stays none.
std::string numberedSubject(const std::string& first, unsigned n);

enum class TriggerState { Waiting, Armed, Triggered, Finished };
const char* toString(TriggerState state);  // "waiting", "armed", "triggered", "finished"

// One session cut by the trigger: samples [first, end) of the stream, with
// the trigger instant at `trigger`.
struct TriggeredSpan {
    std::uint64_t first = 0;
    std::uint64_t trigger = 0;
    std::uint64_t end = 0;
};

class TriggerMachine {
public:
    // Throws std::invalid_argument for a rate that is not positive or times
    // that are negative or not finite.
    TriggerMachine(TriggerSettings settings, double sampleRate_hz);

    // What one sample did.
    struct Step {
        std::optional<TriggeredSpan> started;  // end is not known yet
        std::optional<TriggeredSpan> ended;    // a session complete
    };
    // The watched value of sample `index` (increasing, gaps allowed: a gap
    // is no value, and neither begins nor clears a condition).
    Step push(std::uint64_t index, double value);

    TriggerState state() const { return m_state; }
    // Whether any sample had a value (a derived quantity has none until its
    // mode's zero is taken): before, Waiting is for a first value.
    bool valueSeen() const { return m_valueSeen; }
    unsigned sessionsCut() const { return m_cut; }
    std::uint64_t preSamples() const { return m_pre; }
    const TriggerSettings& settings() const { return m_settings; }

private:
    TriggerSettings m_settings;
    std::uint64_t m_pre, m_post, m_holdOff;
    TriggerState m_state = TriggerState::Waiting;
    std::optional<double> m_previous;
    bool m_valueSeen = false;
    std::optional<std::uint64_t> m_firstSeen;  // the stream's first index: a session reaches back no further
    std::optional<TriggeredSpan> m_open;
    std::optional<std::uint64_t> m_clearedAt;  // the open session's condition cleared here
    std::uint64_t m_rearmAt = 0;               // the hold-off's end
    std::uint64_t m_lastEnd = 0;               // no session overlaps the one before
    unsigned m_cut = 0;
};

}  // namespace tactiscope::core::trigger
