// The papers' probes, compiled into core from resources/profiles/, so the
// CLI, the tests and the GUI start from the same sensor without any file:
// palpation uses the compliance probe of seed 001 (k_H 480, k_L 60 N/m) and
// capacitive the beam No. 1 of seed 002. Panel scan needs no profile.
#pragma once

#include "core/Vocabulary.h"
#include "core/sensors/SensorProfile.h"

#include <optional>
#include <string_view>

namespace tactiscope::core::sensors {

// The profile's JSON text; empty for a mode without one.
std::string_view builtInProfileJson(Mode mode);
std::optional<SensorProfile> builtInProfile(Mode mode);

// Whether `profile` is a probe for `mode`: a compliance pair for palpation,
// a capacitive beam for capacitive; never for panel scan.
bool profileFitsMode(const SensorProfile& profile, Mode mode);
// Which kind of profile a mode takes, for messages ("a compliance pair").
std::string_view profileKindFor(Mode mode);

}  // namespace tactiscope::core::sensors
