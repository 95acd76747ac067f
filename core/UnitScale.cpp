// UnitScale: the capacitance and force units' tables.
#include "core/UnitScale.h"

#include <array>
#include <utility>

namespace tactiscope::core {
namespace {

template <std::size_t N>
std::optional<double> scaleIn(const std::array<std::pair<std::string_view, double>, N>& table, std::string_view unit)
{
    for (const auto& [name, scale] : table)
        if (unit == name) return scale;
    return std::nullopt;
}

}  // namespace

std::optional<double> faradsPer(std::string_view unit)
{
    static constexpr std::array<std::pair<std::string_view, double>, 4> kTable{
        {{"F", 1.0}, {"nF", 1e-9}, {"pF", 1e-12}, {"fF", 1e-15}}};
    return scaleIn(kTable, unit);
}

std::optional<double> newtonsPer(std::string_view unit)
{
    static constexpr std::array<std::pair<std::string_view, double>, 4> kTable{
        {{"N", 1.0}, {"mN", 1e-3}, {"µN", 1e-6}, {"uN", 1e-6}}};
    return scaleIn(kTable, unit);
}

}  // namespace tactiscope::core
