// Text form of numbers for files: the shortest decimal that reads back to
// the very same double, so an export and re-import loses no bit.
#pragma once

#include <string>

namespace tactiscope::core::text {

// Appends the shortest round-trip representation of `value` to `out`.
void appendShortest(std::string& out, double value);
std::string formatShortest(double value);

}  // namespace tactiscope::core::text
