// A clock mapping as stored with a device's part of a session (the
// sessions.clock_json column): a JSON object of the mapping, its
// uncertainty and what that rests on. Read back from a file that may have
// been altered, so reading refuses what is not a mapping instead of
// trusting it.
#pragma once

#include "core/timing/ClockAlignment.h"

#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::timing {

// The stored word: "spread", "bound", "too-few-frames" or "exact".
const char* toString(ClockUncertaintyBasis basis);

// {"reference_s":…,"offset_s":…,"drift":…,"span_s":…,"pairs":…,
//  "uncertainty":"spread"|"bound"|"too-few-frames"|"exact","offset_u_s":…,"drift_u":…,
//  "sample_period_s":…} (the last absent in stores before issue 55: 0)
std::string toJson(const ClockMapping& mapping);
// None for text that is not such an object, or holds a number that is
// not finite, a drift beyond ±1 % (no crystal is that far off: the text
// was altered), a negative uncertainty, an exact one that states one, or
// a sample period below 0 or above an hour.
std::optional<ClockMapping> clockMappingFromJson(std::string_view text);

// The mapping of a stream's own time (`origin_s` being its t = 0 in the
// time `mapping` is given in) onto a session's, whose t = 0 is the host
// instant `sessionStart_host_s`: what a part stores.
ClockMapping onSessionClocks(const ClockMapping& mapping, double origin_s, double sessionStart_host_s);

}  // namespace tactiscope::core::timing
