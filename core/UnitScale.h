// The units a channel's values may be given in (a text board's label
// "force[mN]", an imported column "d [mm]", the command line's --units),
// as the kind of quantity each one is and its factor to the SI unit the
// store keeps (core/ChannelDescriptor.h). One table, so the text decoder,
// the import, the command line, the wizard and the stored sweeps read a
// unit alike.
#pragma once

#include "core/ChannelDescriptor.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core {

struct PhysicalUnit {
    ChannelKind kind = ChannelKind::Other;
    std::string_view si;  // the stored unit: "N", "m", "F"; "" for a strain
    double factor = 1.0;  // SI units per unit: 1e-3 for "mN", 1e-6 for "µε"
};

// Strain ("strain", "ε", "µε", "ue", "µstrain", "microstrain"), force (N, kN, mN, µN,
// uN), length (m, cm, mm, µm, um) and capacitance (F, nF, pF, fF); none
// for another unit, which stays as it was given.
std::optional<PhysicalUnit> physicalUnit(std::string_view unit);
// "count" or "counts": an ADC's raw reading, whose scale a probe's
// converter (or a profile) gives.
bool isCounts(std::string_view unit);
// The channel a device announced with a unit given to it: its kind and
// stored unit from the table (a unit not in it is kept, kind Other); the
// factor that turns its values into the stored unit is returned.
double giveUnit(ChannelDescriptor& channel, std::string_view unit);

// A unit given to channels by name (the command line's --units).
using UnitAssignment = std::map<std::string, std::string>;
// Parses "NAME=UNIT,NAME=UNIT" ("a=µε,b=µε"). Throws std::invalid_argument
// naming the bad item: no '=', no unit, or a channel named twice.
UnitAssignment parseUnitAssignment(std::string_view text);

// Farads per unit; none for another unit.
std::optional<double> faradsPer(std::string_view unit);
// Newtons per unit; none for another unit.
std::optional<double> newtonsPer(std::string_view unit);

}  // namespace tactiscope::core
