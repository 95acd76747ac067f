// The simulator's scenarios by their command-line id ("panel-scan", ...),
// so the GUI, the CLI and the tests create them the same way.
#pragma once

#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::devices::simulator {

std::vector<std::string> scenarioIds();

// A new scenario with default parameters and the given noise seed, or null
// for an unknown id.
std::unique_ptr<SimulatedScenario> makeScenario(std::string_view id, std::uint64_t seed = 1);

}  // namespace tactiscope::devices::simulator
