// Shortest round-trip formatting with std::to_chars.
#include "core/text/NumberFormat.h"

#include <array>
#include <charconv>

namespace tactiscope::core::text {

void appendShortest(std::string& out, double value)
{
    std::array<char, 32> buffer{};  // the longest double is 24 characters
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr);
}

std::string formatShortest(double value)
{
    std::string out;
    appendShortest(out, value);
    return out;
}

}  // namespace tactiscope::core::text
