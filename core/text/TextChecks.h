// What text may be stored and sent anywhere: valid UTF-8 without NUL (a
// PostgreSQL server refuses invalid UTF-8 and cuts text at a NUL), and a
// uuid that is a uuid. A Latin-1 header (µ as the byte 0xB5) is read as
// Latin-1, turned into UTF-8.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::text {

// Why `text` cannot be stored as text ("byte 0xB5 at 3 is not UTF-8", "a
// NUL character at 7"); none when it can.
std::optional<std::string> textProblem(std::string_view text);

// Each byte as the Latin-1 character it is, in UTF-8.
std::string latin1ToUtf8(std::string_view text);

// 8-4-4-4-12 hexadecimal digits.
bool isUuid(std::string_view text);

}  // namespace tactiscope::core::text
