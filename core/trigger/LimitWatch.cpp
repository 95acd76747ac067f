// LimitWatch: the limit's words, hold time to raise, hysteresis to clear.
#include "core/trigger/LimitWatch.h"

#include "core/NumberRanges.h"
#include "core/text/NumberFormat.h"
#include "core/text/ShortQuote.h"
#include "core/units/Dimension.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace tactiscope::core::trigger {
namespace {

std::optional<double> number(std::string_view text)
{
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// A number, or a window LOW..HIGH with its low end below its high end.
std::optional<LimitLevel> levelValue(std::string_view text, bool window)
{
    if (!window) {
        const auto at = number(text);
        return at ? std::optional<LimitLevel>(*at) : std::nullopt;
    }
    const auto dots = text.find("..");
    if (dots == std::string_view::npos) return std::nullopt;
    const auto low = number(text.substr(0, dots)), high = number(text.substr(dots + 2));
    if (!low || !high || !(*low < *high)) return std::nullopt;
    return LimitLevel(*low, *high);
}

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}

// Whether the critical level lies beyond the warning one.
bool ordered(LimitSide side, const LimitLevel& warning, const LimitLevel& critical)
{
    switch (side) {
    case LimitSide::Above:
        return warning.low < critical.low;
    case LimitSide::Below:
        return warning.low > critical.low;
    case LimitSide::Outside:
        return critical.low <= warning.low && warning.high <= critical.high && warning != critical;
    case LimitSide::Inside:
        return warning.low <= critical.low && critical.high <= warning.high && warning != critical;
    }
    return false;
}

// What each side is called, what it clears back to, how its critical level
// must lie, and the sides it guards (bits: past a high level, past a low
// one, within a window); in LimitSide's order.
struct SideFacts {
    const char* name;
    const char* backTo;
    const char* orderRule;
    int guarded;
};
constexpr SideFacts kSideFacts[] = {
    {"above", "below", "above the warning", 1},
    {"below", "above", "below the warning", 2},
    {"inside", "outside", "a window within the warning one", 4},
    {"outside", "inside", "a window around the warning one", 3},
};

const SideFacts& facts(LimitSide side)
{
    return kSideFacts[static_cast<int>(side)];
}

}  // namespace

const char* toString(LimitSeverity severity)
{
    return severity == LimitSeverity::Warning ? "warning" : "critical";
}

const char* toString(LimitSide side)
{
    return facts(side).name;
}

bool isWindow(LimitSide side)
{
    return side == LimitSide::Inside || side == LimitSide::Outside;
}

bool LimitSpec::replaces(const LimitSpec& other) const
{
    return quantity == other.quantity && (facts(side).guarded & facts(other.side).guarded) != 0;
}

std::string LimitSpec::text() const
{
    const auto shown = [this](const LimitLevel& l) {
        return isWindow(side) ? text::formatShortest(l.low) + ".." + text::formatShortest(l.high)
                              : text::formatShortest(l.low);
    };
    std::string t = quantity;
    if (side == LimitSide::Above || side == LimitSide::Below)
        t += side == LimitSide::Above ? ">" : "<";
    else
        t += std::string(" ") + toString(side) + " ";
    if (warning) t += "warning:" + shown(*warning);
    if (warning && critical) t += ",";
    if (critical) t += "critical:" + shown(*critical);
    if (hold_s > 0.0) t += ",hold:" + text::formatShortest(hold_s);
    return t;
}

ParsedLimit parseLimit(std::string_view text)
{
    const auto fail = [](std::string why) { return ParsedLimit{std::nullopt, std::move(why)}; };
    const std::string form =
        "write QUANTITY>warning:W,critical:C (or <), or QUANTITY outside warning:A..B,critical:C..D "
        "(or inside); either level alone; ,hold:S for a hold time";
    const auto op = text.find_first_of("<> ");
    if (op == std::string_view::npos || op == 0) return fail(text::quoteShort(text) + " is no limit: " + form);
    LimitSpec spec;
    spec.quantity = std::string(text.substr(0, op));
    std::string_view rest = text.substr(op + 1);
    if (text[op] != ' ') {
        spec.side = text[op] == '>' ? LimitSide::Above : LimitSide::Below;
    } else {
        rest = trimmed(rest);
        const auto space = rest.find(' ');
        const std::string_view word = rest.substr(0, space);
        if (word != "inside" && word != "outside")
            return fail(text::quoteShort(word) + " is neither inside nor outside: " + form);
        spec.side = word == "inside" ? LimitSide::Inside : LimitSide::Outside;
        rest = space == std::string_view::npos ? std::string_view() : trimmed(rest.substr(space + 1));
    }
    const bool window = isWindow(spec.side);
    while (!rest.empty()) {
        const auto comma = rest.find(',');
        const std::string_view part = rest.substr(0, comma);
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        const auto colon = part.find(':');
        const std::string_view name = part.substr(0, colon);
        const std::string_view value = colon == std::string_view::npos ? std::string_view() : part.substr(colon + 1);
        if (name == "hold") {
            const auto hold = number(value);
            if (!hold || !kLimitHoldRange.holds(*hold))
                return fail(text::quoteShort(part) + " is no hold time (" + kLimitHoldRange.text() + ")");
            spec.hold_s = *hold;
            continue;
        }
        if (name != "warning" && name != "critical")
            return fail(text::quoteShort(name) + " is neither warning, critical nor hold: " + form);
        const auto level = levelValue(value, window);
        if (!level)
            return fail(text::quoteShort(part) +
                        " is no level: " + (window ? "a window is LOW..HIGH, its low end first" : form));
        (name == "warning" ? spec.warning : spec.critical) = level;
    }
    if (!spec.warning && !spec.critical) return fail("a limit needs a warning or a critical level: " + form);
    if (spec.warning && spec.critical && !ordered(spec.side, *spec.warning, *spec.critical))
        return fail(std::string("the critical level must lie beyond the warning one (") + facts(spec.side).orderRule +
                    ")");
    return {spec, {}};
}

namespace {

// The SI prefix that puts `value` between 1 and 1000, and its scale.
std::pair<double, std::string> prefixFor(double value, const std::string& unit)
{
    static constexpr const char* kPrefixes[] = {"f", "p", "n", "µ", "m", "", "k", "M", "G"};
    const int thousands = std::clamp(static_cast<int>(std::floor(std::log10(std::abs(value)) / 3.0)), -5, 3);
    return {std::pow(10.0, -3.0 * thousands), kPrefixes[thousands + 5] + unit};
}

// To `digits` significant digits in plain decimals (1089, not 1.09e+03;
// 0.00001, not 1e-05), trailing zeros dropped; e-notation only beyond
// what plain decimals can show in a line.
std::string significant(double value, int digits)
{
    char text[64];
    const double size = std::abs(value);
    if (!std::isfinite(value) || size == 0.0 || size >= 1e12 || size < 1e-9) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        return text;
    }
    const int decimals = std::max(0, digits - 1 - static_cast<int>(std::floor(std::log10(size))));
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string shown = text;
    if (shown.find('.') != std::string::npos) {
        shown.erase(shown.find_last_not_of('0') + 1);
        if (shown.back() == '.') shown.pop_back();
    }
    return shown;
}

}  // namespace

std::string LimitChange::text(const LimitSpec& spec, const std::string& unit) const
{
    // The value to four digits: enough to see how far past the level it is.
    const auto measured = [unit](double v) { return significant(v, 4) + (unit.empty() ? "" : " " + unit); };
    return text(spec, LimitWording{[](double v) { return text::formatShortest(v); }, measured, unit});
}

LimitWording readableWording(ChannelKind kind, const std::string& unit, double level)
{
    double scale = 1.0;
    std::string shown = unit;
    // A count takes no SI prefix (kcounts reads as nothing anyone uses),
    // nor does a unit that has one (a math channel's µε or mN: kµε reads
    // as nothing either).
    const auto known = units::parseUnit(unit);
    const bool prefixed = kind != ChannelKind::Strain && !unit.empty() && unit != "counts" && unit != "count" &&
                          (!known || known->toSi == 1.0);
    if (kind == ChannelKind::Strain && unit.empty()) {  // a strain is a pure number
        scale = 1e6;
        shown = "µε";
    } else if (prefixed && std::isfinite(level) && level != 0.0) {
        std::tie(scale, shown) = prefixFor(level, unit);
    }
    const std::string suffix = shown.empty() ? "" : " " + shown;
    // Six digits undo the scaling's rounding (0.000956 N is 956 µN, not
    // 955.9999999999999 µN); a measured value to three, in the level's
    // unit unless it lies a thousandfold or more beyond it (a board's counts
    // given a unit they are not in: 3.44 kN, not 3.44e+09 µN).
    const auto measured = [=](double si) {
        const double x = si * scale;
        if (prefixed && std::isfinite(x) && x != 0.0 && (std::abs(x) >= 1e5 || std::abs(x) < 1e-2)) {
            const auto [own, ownUnit] = prefixFor(si, unit);
            return significant(si * own, 3) + " " + ownUnit;
        }
        return significant(x, 3) + suffix;
    };
    return {[scale](double si) { return significant(si * scale, 6); }, measured, shown};
}

std::string LimitChange::text(const LimitSpec& spec, const LimitWording& wording) const
{
    const std::string suffix = wording.unit.empty() ? "" : " " + wording.unit;
    const LimitLevel at = spec.level(severity).value_or(LimitLevel());
    const bool window = isWindow(spec.side);
    const std::string level =
        (window ? wording.level(at.low) + ".." + wording.level(at.high) : wording.level(at.low)) + suffix;
    const std::string what = std::string(" its ") + toString(severity) + (window ? " window " : " limit ");
    if (raised) return spec.quantity + " " + toString(spec.side) + what + level + " (" + wording.measured(value) + ")";
    return spec.quantity + " back " + facts(spec.side).backTo + what + level;
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
    if (!(std::isfinite(m_spec.clear_s) && m_spec.clear_s >= 0.0))
        throw std::invalid_argument("limit: the clear time must be 0 s or more");
    m_hold = static_cast<std::uint64_t>(std::llround(m_spec.hold_s * sampleRate_hz));
    m_clear = static_cast<std::uint64_t>(std::llround(m_spec.clear_s * sampleRate_hz));
    constexpr double infinity = std::numeric_limits<double>::infinity();
    for (int s = 0; s < 2; ++s) {
        const auto& at = m_spec.level(static_cast<LimitSeverity>(s));
        if (!at) continue;
        Level& l = m_level[s];
        l.watched = true;
        l.low = m_spec.side == LimitSide::Above ? -infinity : at->low;
        l.high = m_spec.side == LimitSide::Below ? infinity : at->high;
        l.hysteresis = m_spec.hysteresis_fraction * std::max(std::abs(at->low), std::abs(at->high));
        // A window the value must stay in keeps room to come back to.
        if (m_spec.side == LimitSide::Outside) l.hysteresis = std::min(l.hysteresis, (at->high - at->low) / 4.0);
    }
}

bool LimitWatch::beyond(const Level& l, double value) const
{
    if (m_spec.side == LimitSide::Inside) return l.low < value && value < l.high;
    return value < l.low || value > l.high;
}

// Cleared only back past the level by the hysteresis: noise at the level does not chatter.
bool LimitWatch::back(const Level& l, double value) const
{
    if (m_spec.side == LimitSide::Inside) return value < l.low - l.hysteresis || value > l.high + l.hysteresis;
    return l.low + l.hysteresis < value && value < l.high - l.hysteresis;
}

void LimitWatch::push(std::uint64_t index, double value, std::vector<LimitChange>& changes)
{
    if (std::isnan(value)) return;
    for (int s = 0; s < 2; ++s) {
        Level& l = m_level[s];
        if (!l.watched) continue;
        const auto severity = static_cast<LimitSeverity>(s);
        if (!l.raised) {
            if (!beyond(l, value)) {
                l.beyondSince.reset();
                continue;
            }
            if (!l.beyondSince) l.beyondSince = index;
            // Raised once beyond for the hold time (0: at once).
            if (index + 1 - *l.beyondSince > m_hold) {
                l.raised = true;
                l.beyondSince.reset();
                changes.push_back({severity, true, index, value});
            }
        } else if (!back(l, value)) {
            l.backSince.reset();
        } else {
            if (!l.backSince) l.backSince = index;
            // Cleared once back for the clear time, as raised after the hold.
            if (index + 1 - *l.backSince > m_clear) {
                l.raised = false;
                l.backSince.reset();
                changes.push_back({severity, false, index, value});
            }
        }
    }
}

}  // namespace tactiscope::core::trigger
