// LimitWatch: hold time to raise, hysteresis to clear.
#include "core/trigger/LimitWatch.h"

#include "core/text/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tactiscope::core::trigger {
namespace {

std::optional<double> number(std::string_view text)
{
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

}  // namespace

const char* toString(LimitSeverity severity)
{
    return severity == LimitSeverity::Warning ? "warning" : "critical";
}

std::string LimitSpec::text() const
{
    std::string t = quantity + (above ? ">" : "<");
    if (warning) t += "warning:" + text::formatShortest(*warning);
    if (warning && critical) t += ",";
    if (critical) t += "critical:" + text::formatShortest(*critical);
    if (hold_s > 0.0) t += ",hold:" + text::formatShortest(hold_s);
    return t;
}

ParsedLimit parseLimit(std::string_view text)
{
    const auto fail = [](std::string why) { return ParsedLimit{std::nullopt, std::move(why)}; };
    const std::string form = "write QUANTITY>warning:W,critical:C (or <; either level alone; ,hold:S for a hold time)";
    const auto op = text.find_first_of("<>");
    if (op == std::string_view::npos || op == 0) return fail("'" + std::string(text) + "' is no limit: " + form);
    LimitSpec spec;
    spec.quantity = std::string(text.substr(0, op));
    spec.above = text[op] == '>';
    std::string_view rest = text.substr(op + 1);
    while (!rest.empty()) {
        const auto comma = rest.find(',');
        const std::string_view part = rest.substr(0, comma);
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        const auto colon = part.find(':');
        const std::string_view name = part.substr(0, colon);
        const auto value = colon == std::string_view::npos ? std::nullopt : number(part.substr(colon + 1));
        if (!value) return fail("'" + std::string(part) + "' is no level: " + form);
        if (name == "warning")
            spec.warning = value;
        else if (name == "critical")
            spec.critical = value;
        else if (name == "hold" && *value >= 0.0)
            spec.hold_s = *value;
        else
            return fail("'" + std::string(name) + "' is neither warning, critical nor hold (0 s or more): " + form);
    }
    if (!spec.warning && !spec.critical) return fail("a limit needs a warning or a critical level: " + form);
    if (spec.warning && spec.critical &&
        (spec.above ? *spec.warning >= *spec.critical : *spec.warning <= *spec.critical))
        return fail(std::string("the warning must come before the critical level (") +
                    (spec.above ? "below it" : "above it") + ")");
    return {spec, {}};
}

std::string LimitChange::text(const LimitSpec& spec, const std::string& unit) const
{
    const std::string suffix = unit.empty() ? "" : " " + unit;
    if (!raised)
        return spec.quantity + " back " + (spec.above ? "below" : "above") + " its " + toString(severity) + " limit " +
               text::formatShortest(level) + suffix;
    // The value to four digits: enough to see how far past the level it is.
    char measured[32];
    std::snprintf(measured, sizeof measured, "%.4g", value);
    return spec.quantity + " " + (spec.above ? "above" : "below") + " its " + toString(severity) + " limit " +
           text::formatShortest(level) + suffix + " (" + measured + suffix + ")";
}

LimitWatch::LimitWatch(LimitSpec spec, double sampleRate_hz)
    : m_spec(std::move(spec))
{
    if (!(std::isfinite(sampleRate_hz) && sampleRate_hz > 0.0))
        throw std::invalid_argument("limit: the sample rate must be positive");
    if (!(std::isfinite(m_spec.hold_s) && m_spec.hold_s >= 0.0))
        throw std::invalid_argument("limit: the hold time must be 0 s or more");
    if (!(std::isfinite(m_spec.hysteresis_fraction) && m_spec.hysteresis_fraction >= 0.0))
        throw std::invalid_argument("limit: the hysteresis must be 0 or more");
    m_hold = static_cast<std::uint64_t>(std::llround(m_spec.hold_s * sampleRate_hz));
    m_level[0].at = m_spec.warning;
    m_level[1].at = m_spec.critical;
    for (Level& l : m_level)
        if (l.at) l.hysteresis = m_spec.hysteresis_fraction * std::abs(*l.at);
}

void LimitWatch::push(std::uint64_t index, double value, std::vector<LimitChange>& changes)
{
    if (std::isnan(value)) return;
    for (int s = 0; s < 2; ++s) {
        Level& l = m_level[s];
        if (!l.at) continue;
        const double level = *l.at;
        const bool beyond = m_spec.above ? value > level : value < level;
        // Cleared only back past the level by the hysteresis: noise at the level does not chatter.
        const bool back = m_spec.above ? value < level - l.hysteresis : value > level + l.hysteresis;
        const auto severity = static_cast<LimitSeverity>(s);
        if (!l.raised) {
            if (!beyond) {
                l.beyondSince.reset();
                continue;
            }
            if (!l.beyondSince) l.beyondSince = index;
            // Raised once beyond for the hold time (0: at once).
            if (index + 1 - *l.beyondSince > m_hold) {
                l.raised = true;
                l.beyondSince.reset();
                changes.push_back({severity, true, index, value, level});
            }
        } else if (back) {
            l.raised = false;
            changes.push_back({severity, false, index, value, level});
        }
    }
}

}  // namespace tactiscope::core::trigger
