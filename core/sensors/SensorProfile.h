// Sensor profiles: the JSON files that describe a probe's mechanics, in SI
// units, with the exact keys other tools write:
//   {"kind": "cantilever", "name": "...", "length_m": 0.05, "width_m": 0.01,
//    "thickness_m": 0.002, "youngs_modulus_pa": 3e9}
//   {"kind": "compliance_pair", "name": "...", "high": {cantilever keys},
//    "low": {cantilever keys}}
//   {"kind": "capacitive_beam", "name": "...",
//    "beam": {"length_m", "root_width_m", "thickness_m", "youngs_modulus_pa",
//             "sheet_length_ratio"},
//    "sheet_layers": [{"name", "thickness_m", "youngs_modulus_pa"}, …],
//    "c0_pf": 51.44, optional "c_edl_pf"}
//   (sheet layers from the beam surface outward)
// A compliance pair and a capacitive beam may say which channels of their
// device play which role: optional "roles": {"ch1": "stiff-beam", …}
// (core/modes/ChannelRoles.h). A compliance pair may give the scale of
// beams read in raw counts: optional "channels": {"ch1": {"unit": "mN",
// "counts_per_unit": 20.48, "full_scale": 32767}, …}
// (core/sensors/ChannelScale.h); a capacitive beam, of its capacitance in
// counts: {"c": {"unit": "pF", "counts_per_unit": 2048000, "offset":
// 8388608}} (core/capacitive/CapacitanceInput.h).
// Loading validates everything and reports the first problem with the key
// that has it ("high.thickness_m: must be a positive number"); unknown keys
// are errors too, so a misspelt key is not silently ignored.
#pragma once

#include "core/modes/ChannelRoles.h"
#include "core/sensors/CantileverBeam.h"
#include "core/sensors/CapacitiveBeam.h"
#include "core/sensors/ChannelScale.h"
#include "core/trigger/LimitWatch.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace tactiscope::core::sensors {

struct CantileverProfile {
    std::string name;
    CantileverGeometry geometry;
};

// A probe's limit alarms (core/trigger/LimitWatch.h), as "limits":
// ["force>warning:0.0005,critical:0.0008", …]; none given: the sensor
// model's (core/sensors/SensorLimits.h); an empty list: no alarms.
using ProfileLimits = std::optional<std::vector<trigger::LimitSpec>>;

struct CompliancePairProfile {
    std::string name;
    CantileverGeometry high;
    CantileverGeometry low;
    RoleAssignment roles{};  // by channel name; empty: the device's own
    ProfileLimits limits{};
    ChannelScales channels{};  // beams in counts the device does not scale itself
};

struct CapacitiveBeamProfile {
    std::string name;
    CapacitiveBeamGeometry geometry;
    RoleAssignment roles{};
    ProfileLimits limits{};
    ChannelScales channels{};  // a capacitance in counts the device does not scale itself
    // Its baseline stability, a random walk in F/√s ("baseline_wander_pf_per_sqrt_s"):
    // the calibration's ± then holds the baseline's wander between its zeros.
    std::optional<double> baselineWander_f_per_sqrt_s{};
};

using SensorProfile = std::variant<CantileverProfile, CompliancePairProfile, CapacitiveBeamProfile>;

// One line for the user: "<source>: <key>: <problem>".
class ProfileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A profile holds a few dozen numbers and names: a larger text is refused
// before it is parsed (a 32 MB array once kept the window from appearing).
inline constexpr std::size_t kMostProfileBytes = 1 << 20;
// A profile's name, as lists and reports show it.
inline constexpr std::size_t kMostProfileNameCharacters = 200;

// `source` names the text in messages (usually the file name). Throws
// ProfileError; its message quotes at most a few dozen characters of a bad
// value.
SensorProfile parseSensorProfile(std::string_view json, const std::string& source);
// Refuses a file larger than kMostProfileBytes without reading it.
SensorProfile loadSensorProfile(const std::string& path);
// The refusal of a profile text of `bytes` bytes, when it is too large.
void refuseOversizedProfile(std::uintmax_t bytes, const std::string& source);

// The profile as JSON with the keys above (for export and for storing with a
// session).
std::string toJson(const SensorProfile& profile);
const std::string& profileName(const SensorProfile& profile);
// The channel roles the profile gives (none for a single cantilever); a
// capacitive beam's channel it scales plays the capacitance unless given
// another role.
RoleAssignment profileRoles(const SensorProfile& profile);
// The channel scales the profile gives (a compliance pair's or a
// capacitive beam's; none for a single cantilever).
ChannelScales profileScales(const SensorProfile& profile);

}  // namespace tactiscope::core::sensors
