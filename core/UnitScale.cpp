// UnitScale: the table of units, by kind.
#include "core/UnitScale.h"

#include "core/text/NamedList.h"
#include "core/text/ShortQuote.h"

#include <array>
#include <cctype>
#include <stdexcept>

namespace tactiscope::core {
namespace {

struct UnitName {
    std::string_view name;
    PhysicalUnit unit;
};

constexpr std::array kUnits{
    UnitName{"strain", {ChannelKind::Strain, "", 1.0}},
    UnitName{"ε", {ChannelKind::Strain, "", 1.0}},
    UnitName{"µε", {ChannelKind::Strain, "", 1e-6}},
    UnitName{"με", {ChannelKind::Strain, "", 1e-6}},  // Greek mu, as some keyboards type it
    UnitName{"uε", {ChannelKind::Strain, "", 1e-6}},
    UnitName{"ue", {ChannelKind::Strain, "", 1e-6}},
    UnitName{"microstrain", {ChannelKind::Strain, "", 1e-6}},
    UnitName{"µstrain", {ChannelKind::Strain, "", 1e-6}},
    UnitName{"N", {ChannelKind::Force, "N", 1.0}},
    UnitName{"kN", {ChannelKind::Force, "N", 1e3}},
    UnitName{"mN", {ChannelKind::Force, "N", 1e-3}},
    UnitName{"µN", {ChannelKind::Force, "N", 1e-6}},
    UnitName{"uN", {ChannelKind::Force, "N", 1e-6}},
    UnitName{"m", {ChannelKind::Position, "m", 1.0}},
    UnitName{"cm", {ChannelKind::Position, "m", 1e-2}},
    UnitName{"mm", {ChannelKind::Position, "m", 1e-3}},
    UnitName{"µm", {ChannelKind::Position, "m", 1e-6}},
    UnitName{"um", {ChannelKind::Position, "m", 1e-6}},
    UnitName{"F", {ChannelKind::Capacitance, "F", 1.0}},
    UnitName{"nF", {ChannelKind::Capacitance, "F", 1e-9}},
    UnitName{"pF", {ChannelKind::Capacitance, "F", 1e-12}},
    UnitName{"fF", {ChannelKind::Capacitance, "F", 1e-15}},
};

std::optional<double> factorOf(std::string_view unit, ChannelKind kind)
{
    const auto physical = physicalUnit(unit);
    if (!physical || physical->kind != kind) return std::nullopt;
    return physical->factor;
}

// The unit of the table spelt as `unit` in another case ("MN" for mN,
// "PF" for pF): a slip, since a unit's case is part of it (M is mega).
std::optional<std::string_view> otherCaseOf(std::string_view unit)
{
    const auto lower = [](std::string_view text) {
        std::string folded(text);
        for (char& c : folded) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return folded;
    };
    for (const auto& entry : kUnits)
        if (entry.name != unit && lower(entry.name) == lower(unit)) return entry.name;
    return std::nullopt;
}

}  // namespace

std::optional<PhysicalUnit> physicalUnit(std::string_view unit)
{
    for (const auto& [name, physical] : kUnits)
        if (unit == name) return physical;
    return std::nullopt;
}

bool isCounts(std::string_view unit)
{
    return unit == "count" || unit == "counts";
}

double giveUnit(ChannelDescriptor& channel, std::string_view unit)
{
    const auto physical = physicalUnit(unit);
    channel.kind = physical ? physical->kind : ChannelKind::Other;
    channel.unit = physical ? std::string(physical->si) : std::string(unit);
    return physical ? physical->factor : 1.0;
}

UnitAssignment parseUnitAssignment(std::string_view text)
{
    UnitAssignment units;
    for (auto& [name, unit] : text::parseNamedList(text, "NAME=UNIT (e.g. a=µε)", "unit")) {
        if (unit.empty()) throw std::invalid_argument("channel '" + name + "' is given no unit");
        // "force=mN;pos=mm": one item, whose unit would swallow the next.
        if (unit.find_first_of("=;") != std::string::npos)
            throw std::invalid_argument(text::quoteShort(unit) + " is not a unit (separate the items with ',')");
        if (!physicalUnit(unit))
            if (const auto meant = otherCaseOf(unit))
                throw std::invalid_argument(text::quoteShort(unit) + " (" + text::shortened(name) + "): did you mean " +
                                            std::string(*meant) + "? A unit's case is part of it");
        units.emplace(std::move(name), std::move(unit));
    }
    return units;
}

std::optional<double> faradsPer(std::string_view unit)
{
    return factorOf(unit, ChannelKind::Capacitance);
}

std::optional<double> newtonsPer(std::string_view unit)
{
    return factorOf(unit, ChannelKind::Force);
}

}  // namespace tactiscope::core
