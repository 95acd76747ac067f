// Limit alarms on one channel or derived quantity (issue 39): a warning and
// a critical level, above or below which the value must stay for a hold
// time to raise its alarm, and back past the level by a hysteresis to clear
// it, so noise at the level does not chatter. The rules live below the UI:
// the CLI (`record --limit`) and the GUI share them.
//   force>warning:0.002,critical:0.003    above: 2 mN warns, 3 mN is critical
//   a<warning:-8e-4,critical:-1e-3         below
//   force>critical:0.003,hold:0.2          beyond it for 0.2 s before it is raised
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::trigger {

enum class LimitSeverity { Warning, Critical };
const char* toString(LimitSeverity severity);  // "warning", "critical"

struct LimitSpec {
    std::string quantity;
    bool above = true;  // the alarm is for values above the levels (else below)
    std::optional<double> warning, critical;
    // Back past a level by this much clears its alarm (SI; by default 2 %
    // of the level's size); beyond it this long raises it.
    double hysteresis_fraction = 0.02;
    double hold_s = 0.0;

    std::string text() const;  // back in the form above
};

struct ParsedLimit {
    std::optional<LimitSpec> limit;
    std::string error;
};
// "QUANTITY>warning:W,critical:C[,hold:S]" (either level may be left out,
// not both; above, a warning below its critical; below, above it).
ParsedLimit parseLimit(std::string_view text);

// A raised or cleared alarm: at sample `index`, the value then, the level.
struct LimitChange {
    LimitSeverity severity = LimitSeverity::Warning;
    bool raised = true;
    std::uint64_t index = 0;
    double value = 0.0;
    double level = 0.0;
    // "force above its critical limit 0.003 N (0.0031 N)", in the quantity's SI unit.
    std::string text(const LimitSpec& spec, const std::string& unit = {}) const;
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
    struct Level {
        std::optional<double> at;
        double hysteresis = 0.0;
        bool raised = false;
        std::optional<std::uint64_t> beyondSince;  // first sample of the current run beyond the level
    };
    LimitSpec m_spec;
    std::uint64_t m_hold;
    Level m_level[2];
};

}  // namespace tactiscope::core::trigger
