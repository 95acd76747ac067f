// SI units per stored unit of the quantities a calibration reads from
// channels of any device: a capacitance (F, nF, pF, fF) and a force (N, mN,
// µN or uN). One table, so the command line, the wizard and the stored
// sweeps read a channel's unit alike.
#pragma once

#include <optional>
#include <string_view>

namespace tactiscope::core {

// Farads per unit; none for another unit.
std::optional<double> faradsPer(std::string_view unit);
// Newtons per unit; none for another unit.
std::optional<double> newtonsPer(std::string_view unit);

}  // namespace tactiscope::core
