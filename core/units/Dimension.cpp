// Unit symbols, prefixes and the parsing of their products and quotients.
#include "core/units/Dimension.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace tactiscope::core::units {
namespace {

struct Symbol {
    std::string_view name;
    Unit unit;
};

constexpr Dimension dim(double m, double kg, double s, double a = 0.0, double count = 0.0)
{
    return Dimension{{m, kg, s, a, count}};
}

// The symbols, each with its dimension and its factor to SI. Strain is
// a pure number (ε = 1, µε = 1e-6).
const std::array kSymbols{
    Symbol{"m", {dim(1, 0, 0), 1.0}},
    Symbol{"g", {dim(0, 1, 0), 1e-3}},
    Symbol{"s", {dim(0, 0, 1), 1.0}},
    Symbol{"A", {dim(0, 0, 0, 1), 1.0}},
    Symbol{"N", {dim(1, 1, -2), 1.0}},
    Symbol{"Pa", {dim(-1, 1, -2), 1.0}},
    Symbol{"Hz", {dim(0, 0, -1), 1.0}},
    Symbol{"F", {dim(-2, -1, 4, 2), 1.0}},
    Symbol{"V", {dim(2, 1, -3, -1), 1.0}},
    Symbol{"Ω", {dim(2, 1, -3, -2), 1.0}},
    Symbol{"ohm", {dim(2, 1, -3, -2), 1.0}},
    Symbol{"strain", {dim(0, 0, 0), 1.0}},
    Symbol{"ε", {dim(0, 0, 0), 1.0}},
    Symbol{"count", {dim(0, 0, 0, 0, 1), 1.0}},
    Symbol{"counts", {dim(0, 0, 0, 0, 1), 1.0}},
    Symbol{"%", {dim(0, 0, 0), 1e-2}},
};

const std::array<std::pair<std::string_view, double>, 11> kPrefixes{{
    {"p", 1e-12},
    {"n", 1e-9},
    {"µ", 1e-6},
    {"u", 1e-6},
    {"μ", 1e-6},  // the Greek letter, as some keyboards give it
    {"m", 1e-3},
    {"c", 1e-2},
    {"k", 1e3},
    {"M", 1e6},
    {"G", 1e9},
    {"f", 1e-15},
}};

std::optional<Unit> symbolUnit(std::string_view token)
{
    for (const Symbol& s : kSymbols)
        if (token == s.name) return s.unit;
    // A prefixed symbol; the count and a percentage take none.
    for (const auto& [prefix, factor] : kPrefixes) {
        if (!token.starts_with(prefix)) continue;
        const std::string_view rest = token.substr(prefix.size());
        for (const Symbol& s : kSymbols)
            if (rest == s.name && s.name != "count" && s.name != "counts" && s.name != "%" && s.name != "strain")
                return Unit{s.unit.dimension, s.unit.toSi * factor};
    }
    return std::nullopt;
}

// "N", "m^2", "s^-2", "s⁻²" is not read: powers are written with '^'.
std::optional<Unit> factorUnit(std::string_view token)
{
    int power = 1;
    if (const auto caret = token.find('^'); caret != std::string_view::npos) {
        const std::string digits(token.substr(caret + 1));
        char* end = nullptr;
        const long value = std::strtol(digits.c_str(), &end, 10);
        if (digits.empty() || *end != '\0' || value < -9 || value > 9 || value == 0) return std::nullopt;
        power = static_cast<int>(value);
        token = token.substr(0, caret);
    }
    if (token == "1") return Unit{};
    const auto unit = symbolUnit(token);
    if (!unit) return std::nullopt;
    Unit raised{{}, std::pow(unit->toSi, power)};
    for (std::size_t k = 0; k < kBaseDimensions; ++k)
        raised.dimension.exponents[k] = unit->dimension.exponents[k] * power;
    return raised;
}

}  // namespace

bool Dimension::dimensionless() const
{
    for (const double e : exponents)
        if (e != 0.0) return false;
    return true;
}

std::string Dimension::text() const
{
    static constexpr std::array<const char*, kBaseDimensions> kNames{"m", "kg", "s", "A", "count"};
    std::string out;
    for (std::size_t k = 0; k < kBaseDimensions; ++k) {
        const double e = exponents[k];
        if (e == 0.0) continue;
        if (!out.empty()) out += ' ';
        out += kNames[k];
        if (e != 1.0) {
            char power[16];
            std::snprintf(power, sizeof power, "^%g", e);
            out += power;
        }
    }
    return out.empty() ? "1" : out;
}

std::optional<Unit> parseUnit(std::string_view text)
{
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    if (text.empty()) return Unit{};
    Unit result;
    double sign = 1.0;  // before '/': multiply; after: divide
    std::size_t start = 0;
    const auto take = [&](std::size_t end) -> bool {
        const auto unit = factorUnit(text.substr(start, end - start));
        if (!unit) return false;
        for (std::size_t k = 0; k < kBaseDimensions; ++k)
            result.dimension.exponents[k] += sign * unit->dimension.exponents[k];
        result.toSi *= sign > 0.0 ? unit->toSi : 1.0 / unit->toSi;
        return true;
    };
    for (std::size_t i = 0; i <= text.size(); ++i) {
        const bool end = i == text.size();
        // '·' is two bytes in UTF-8 (0xC2 0xB7).
        const bool dot = !end && text.substr(i).starts_with("·");
        if (end || text[i] == '*' || text[i] == '/' || dot) {
            if (!take(i)) return std::nullopt;
            if (!end && text[i] == '/') {
                if (sign < 0.0) return std::nullopt;  // "a/b/c" is not read: ambiguous to people
                sign = -1.0;
            }
            start = i + (dot ? 2 : 1);
            if (dot) ++i;
        }
    }
    return result;
}

}  // namespace tactiscope::core::units
