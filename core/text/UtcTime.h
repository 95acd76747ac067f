// Wall-clock times as stored and shown: ISO 8601 UTC with milliseconds,
// e.g. 2026-11-21T14:20:28.123Z, which sorts as text in time order.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::text {

std::string utcIso8601(std::chrono::system_clock::time_point time);
inline std::string utcNow()
{
    return utcIso8601(std::chrono::system_clock::now());
}

// Seconds since 1970 of a time in that form (fractional seconds of any
// length, or none), or nothing for any other text: stored times come from
// files and servers this program does not trust.
std::optional<double> utcSeconds(std::string_view iso8601);

}  // namespace tactiscope::core::text
