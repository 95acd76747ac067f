// TriggerCondition: the words of a trigger and their test on a value.
#include "core/trigger/TriggerCondition.h"

#include "core/text/NumberFormat.h"
#include "core/text/ShortQuote.h"

#include <charconv>
#include <cmath>
#include <utility>

namespace tactiscope::core::trigger {
namespace {

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

std::optional<double> number(std::string_view text)
{
    text = trimmed(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

ParsedTrigger failure(std::string why)
{
    return {std::nullopt, std::move(why)};
}

}  // namespace

bool TriggerCondition::holds(double value) const
{
    switch (kind) {
    case TriggerKind::Above:
    case TriggerKind::Rising:
        return value > level;
    case TriggerKind::Below:
    case TriggerKind::Falling:
        return value < level;
    case TriggerKind::Inside:
        return value >= level && value <= high;
    case TriggerKind::Outside:
        return value < level || value > high;
    }
    return false;
}

bool TriggerCondition::begins(std::optional<double> previous, double value) const
{
    if (!holds(value)) return false;
    // The first value seen begins a level or window; an edge needs the value before it.
    if (!previous || std::isnan(*previous)) return !isEdge();
    return !holds(*previous);
}

std::string TriggerCondition::text() const
{
    const auto n = [](double v) { return text::formatShortest(v); };
    switch (kind) {
    case TriggerKind::Above:
        return quantity + ">" + n(level);
    case TriggerKind::Below:
        return quantity + "<" + n(level);
    case TriggerKind::Rising:
        return quantity + " rising " + n(level);
    case TriggerKind::Falling:
        return quantity + " falling " + n(level);
    case TriggerKind::Inside:
        return quantity + " inside " + n(level) + ".." + n(high);
    case TriggerKind::Outside:
        return quantity + " outside " + n(level) + ".." + n(high);
    }
    return quantity;
}

std::string TriggerCondition::readableText(const std::function<std::string(double)>& n, const std::string& unit) const
{
    const std::string in = unit.empty() ? "" : " " + unit;
    switch (kind) {
    case TriggerKind::Above:
        return quantity + " above " + n(level) + in;
    case TriggerKind::Below:
        return quantity + " below " + n(level) + in;
    case TriggerKind::Rising:
        return quantity + " rising through " + n(level) + in;
    case TriggerKind::Falling:
        return quantity + " falling through " + n(level) + in;
    case TriggerKind::Inside:
        return quantity + " inside " + n(level) + ".." + n(high) + in;
    case TriggerKind::Outside:
        return quantity + " outside " + n(level) + ".." + n(high) + in;
    }
    return quantity;
}

ParsedTrigger parseTrigger(std::string_view text)
{
    text = trimmed(text);
    const std::string_view forms = "write QUANTITY>LEVEL, QUANTITY<LEVEL, QUANTITY rising LEVEL, QUANTITY falling "
                                   "LEVEL, QUANTITY inside LOW..HIGH or QUANTITY outside LOW..HIGH";
    if (const auto op = text.find_first_of("<>"); op != std::string_view::npos) {
        TriggerCondition c;
        c.quantity = std::string(trimmed(text.substr(0, op)));
        c.kind = text[op] == '>' ? TriggerKind::Above : TriggerKind::Below;
        const auto level = number(text.substr(op + 1));
        if (c.quantity.empty()) return failure("the trigger names no quantity: " + std::string(forms));
        if (!level)
            return failure(text::quoteShort(trimmed(text.substr(op + 1))) + " is no level: " + std::string(forms));
        c.level = *level;
        return {c, {}};
    }
    const auto space = text.find(' ');
    if (space == std::string_view::npos)
        return failure(text::quoteShort(text) + " is no trigger: " + std::string(forms));
    TriggerCondition c;
    c.quantity = std::string(text.substr(0, space));
    std::string_view rest = trimmed(text.substr(space + 1));
    const auto wordEnd = rest.find(' ');
    const std::string_view word = rest.substr(0, wordEnd);
    const std::string_view argument = wordEnd == std::string_view::npos ? std::string_view() : rest.substr(wordEnd + 1);
    if (word == "rising" || word == "falling") {
        c.kind = word == "rising" ? TriggerKind::Rising : TriggerKind::Falling;
        const auto level = number(argument);
        if (!level) return failure(text::quoteShort(trimmed(argument)) + " is no level: " + std::string(forms));
        c.level = *level;
        return {c, {}};
    }
    if (word == "inside" || word == "outside") {
        c.kind = word == "inside" ? TriggerKind::Inside : TriggerKind::Outside;
        const auto dots = argument.find("..");
        const auto low = dots == std::string_view::npos ? std::nullopt : number(argument.substr(0, dots));
        const auto high = dots == std::string_view::npos ? std::nullopt : number(argument.substr(dots + 2));
        if (!low || !high) return failure(text::quoteShort(trimmed(argument)) + " is no window LOW..HIGH");
        if (!(*low < *high)) return failure("a window's low end must be below its high end");
        c.level = *low;
        c.high = *high;
        return {c, {}};
    }
    return failure(text::quoteShort(word) + " is no trigger word: " + std::string(forms));
}

}  // namespace tactiscope::core::trigger
