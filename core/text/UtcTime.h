// Wall-clock times as stored and shown: ISO 8601 UTC with milliseconds,
// e.g. 2026-11-21T14:20:28.123Z, which sorts as text in time order.
#pragma once

#include <chrono>
#include <string>

namespace tactiscope::core::text {

std::string utcIso8601(std::chrono::system_clock::time_point time);
inline std::string utcNow()
{
    return utcIso8601(std::chrono::system_clock::now());
}

}  // namespace tactiscope::core::text
