// parseTextLine: the Serial Plotter's fields, NAME=VALUE pairs and Teleplot.
#include "devices/protocol/TextLine.h"

#include "core/text/NoNumber.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace tactiscope::devices::protocol {

namespace {

bool separator(char c)
{
    return c == ',' || c == ' ' || c == '\t' || c == '\r';
}

std::string lowered(std::string_view text)
{
    std::string result(text);
    std::ranges::transform(result, result.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return result;
}

// Seconds per unit of a time unit's usual spellings; none for others.
std::optional<double> secondsPerUnit(std::string_view unit)
{
    const std::string u = lowered(unit);
    if (u == "s") return 1.0;
    if (u == "ms") return 1e-3;
    if (u == "us" || u == "\xC2\xB5s" || u == "\xCE\xBCs") return 1e-6;  // µs, with the micro sign or mu
    return std::nullopt;
}

// "force[mN]" → ("force", "mN"); a label without brackets is all name.
std::pair<std::string, std::string> splitUnit(std::string_view label)
{
    const auto open = label.find('[');
    const auto close = label.find(']', open == std::string_view::npos ? 0 : open);
    if (open == std::string_view::npos || close == std::string_view::npos) return {std::string(label), std::string()};
    return {std::string(label.substr(0, open)) + std::string(label.substr(close + 1)),
            std::string(label.substr(open + 1, close - open - 1))};
}

// A field that is the board's clock: a labelled t, time or timestamp (its
// unit told by a bracket, or found from the arrivals), millis or micros.
std::optional<BoardTime> boardTimeOf(const TextField& field)
{
    const std::string name = lowered(field.label);
    if (name == "millis") return BoardTime{field.value, 1e-3};
    if (name == "micros") return BoardTime{field.value, 1e-6};
    if (name == "t" || name == "time" || name == "timestamp")
        return BoardTime{field.value, field.unit.empty() ? std::nullopt : secondsPerUnit(field.unit)};
    return std::nullopt;
}

// ">NAME:VALUE[§UNIT][|FLAGS]" or ">NAME:TIMESTAMP:VALUE…" (Teleplot).
// Text values (flag t) and XY points (flag xy) are no samples.
ParsedLine parseTeleplot(std::string_view text)
{
    text.remove_prefix(1);
    while (!text.empty() && separator(text.back())) text.remove_suffix(1);
    std::string_view flags;
    if (const auto bar = text.find('|'); bar != std::string_view::npos) {
        flags = text.substr(bar + 1);
        text = text.substr(0, bar);
    }
    if (flags.find('t') != std::string_view::npos || flags.find("xy") != std::string_view::npos) return {};
    std::string unit;
    if (const auto section = text.find("\xC2\xA7"); section != std::string_view::npos) {  // '§' in UTF-8
        unit = std::string(text.substr(section + 2));
        text = text.substr(0, section);
    }
    const auto colon = text.find(':');
    if (colon == std::string_view::npos || colon == 0) return {};
    TextLine line;
    line.teleplot = true;
    std::string_view rest = text.substr(colon + 1);
    if (const auto second = rest.find(':'); second != std::string_view::npos) {
        const auto stamp = parseBoardNumber(rest.substr(0, second));
        if (!stamp) return {};
        line.boardTime = BoardTime{*stamp, 1e-3};
        rest = rest.substr(second + 1);
    }
    const auto value = parseBoardValue(rest);
    if (!value) return {};
    line.fields.push_back({std::string(text.substr(0, colon)), std::move(unit), *value});
    return {std::move(line), LineRefusal::NotNumbers};
}

}  // namespace

std::optional<double> parseBoardNumber(std::string_view token)
{
    if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || error != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::optional<double> parseBoardValue(std::string_view token)
{
    if (auto number = parseBoardNumber(token)) return number;
    if (core::text::spellsNoNumber(token)) return std::numeric_limits<double>::quiet_NaN();
    return std::nullopt;
}

bool hasNumber(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && separator(text[i])) ++i;
        std::size_t end = i;
        while (end < text.size() && !separator(text[end])) ++end;
        std::string_view token = text.substr(i, end - i);
        if (const auto mark = token.find_last_of(":="); mark != std::string_view::npos) token.remove_prefix(mark + 1);
        if (!token.empty() && parseBoardNumber(token)) return true;
        i = end;
    }
    return false;
}

ParsedLine parseTextLine(std::string_view text)
{
    const auto start = std::ranges::find_if_not(text, separator);
    if (start == text.end()) return {std::nullopt, LineRefusal::Blank};
    text.remove_prefix(static_cast<std::size_t>(start - text.begin()));
    if (text.front() == '>') return parseTeleplot(text);
    TextLine line;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && separator(text[i])) ++i;
        if (i == text.size()) break;
        std::size_t end = i;
        while (end < text.size() && !separator(text[end])) ++end;
        std::string_view token = text.substr(i, end - i);
        i = end;
        TextField field;
        // LABEL:VALUE or NAME=VALUE; the last of them, so that a label may
        // hold a ':' of its own.
        if (const auto mark = token.find_last_of(":="); mark != std::string_view::npos) {
            std::tie(field.label, field.unit) = splitUnit(token.substr(0, mark));
            token.remove_prefix(mark + 1);
        }
        const auto value = parseBoardValue(token);
        if (!value) return {};
        field.value = *value;
        if (auto time = boardTimeOf(field); time && !line.boardTime) {
            if (!std::isfinite(time->value)) return {};  // a clock that reads no number times nothing
            line.boardTime = time;
            continue;
        }
        line.fields.push_back(std::move(field));
    }
    if (line.fields.empty()) return {};  // a time alone is no sample
    return {std::move(line), LineRefusal::NotNumbers};
}

}  // namespace tactiscope::devices::protocol
