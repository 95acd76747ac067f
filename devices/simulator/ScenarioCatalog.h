// The simulator's scenarios by their command-line id ("panel-scan", ...),
// so the GUI, the CLI and the tests create them the same way.
#pragma once

#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::devices::simulator {

// The scenarios of the two hand-held probes are named after their modes.
inline const std::string kPanelScanScenario{core::toString(core::Mode::PanelScan)};
inline const std::string kPalpationScenario{core::toString(core::Mode::Palpation)};
// Panels passing a station, each stroked once (2 s), then 3 s at rest
// while the next comes: a triggered recording's "one session per panel".
inline const std::string kPanelLineScenario{"panel-line"};
inline constexpr double kPanelLineRest_s = 3.0;
// The panel probe at rest on its stand: its gauges' noise only, for a zero
// or a shunt check (its bridges switch a shunt: ShuntedBridges.h).
inline const std::string kPanelRestScenario{"panel-rest"};
// The extra-soft capacitive beam overloaded: the weights of
// capacitive-weights (10 to 150 mgf), half a second each, after 2 s
// unloaded; past its safe force (0.6 mN warns, 0.96 mN is critical) from
// 5 s and 6.5 s.
inline const std::string kCapacitiveOverloadScenario{"capacitive-overload"};

// A reference load cell (LoadCellScenario.h, kLoadCellScenario) is one
// too: a second device to calibrate the capacitive beam against.
std::vector<std::string> scenarioIds();

// A new scenario with default parameters, the given noise seed and, when
// given, another sample rate; null for an unknown id. Throws
// std::invalid_argument for a non-positive rate.
std::unique_ptr<SimulatedScenario> makeScenario(std::string_view id, std::uint64_t seed = 1,
                                                std::optional<double> rate_hz = std::nullopt);

}  // namespace tactiscope::devices::simulator
