// Physical dimensions and the units a user types for a math channel
// ("N/m", "mN/mm", "pF", "µε", "1"): each unit is a dimension (exponents
// of metre, kilogram, second, ampere and an ADC's count, which is kept a
// dimension of its own so counts never add to newtons) and a factor to SI.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::units {

inline constexpr std::size_t kBaseDimensions = 5;  // m, kg, s, A, count

struct Dimension {
    std::array<double, kBaseDimensions> exponents{};  // halves allowed (a square root)

    bool dimensionless() const;
    friend bool operator==(const Dimension&, const Dimension&) = default;
    // "kg·m·s⁻²" as "m kg s^-2"; "1" when dimensionless.
    std::string text() const;
};

struct Unit {
    Dimension dimension;
    double toSi = 1.0;  // SI units per one of this unit
};

// Parses a product and quotient of unit symbols with SI prefixes and
// integer powers: "N/m", "mN/mm", "m/s^2", "N*m", "N·m", "pF", "µε",
// "strain", "1" or "" (dimensionless), "count". Nothing for text it cannot
// read.
std::optional<Unit> parseUnit(std::string_view text);

}  // namespace tactiscope::core::units
