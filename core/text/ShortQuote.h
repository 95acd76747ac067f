// A value the user gave, in a message: whole when short, else its first 40
// characters and its length, so that a pasted file's worth of text in an
// option (a 100 kB --trigger) is not echoed back whole. One helper for
// every message that repeats what it refuses.
#pragma once

#include <string>
#include <string_view>

namespace tactiscope::core::text {

inline constexpr std::size_t kMostQuoted = 40;  // characters (UTF-8 code points)

// "a>0.5", or "a>0.50000000000000000000000000000000000… (100000 characters)".
std::string shortened(std::string_view value);
// The same in quotes: "'a>0.5'", "'a>0.5000…' (100000 characters)".
std::string quoteShort(std::string_view value);

}  // namespace tactiscope::core::text
