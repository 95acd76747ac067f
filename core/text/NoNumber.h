// What boards and programs print for a value that is no number: "nan",
// "inf", "-inf", "infinity" (printf, Serial.print of a float, numpy), "ovf"
// (Serial.print of a float beyond 4.3e9), in any case, with a sign or not.
// Read as a hole in that value's channel alone, by the live text decoder
// and by import alike.
#pragma once

#include <string_view>

namespace tactiscope::core::text {

bool spellsNoNumber(std::string_view token);

}  // namespace tactiscope::core::text
