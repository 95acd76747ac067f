// NumberRange's words.
#include "core/NumberRanges.h"

#include <cstdio>

namespace tactiscope::core {

namespace {

// A bound as plain digits (100000, 0.000001), never "1e+05": the bounds
// are round numbers a user types back.
std::string plain(double value)
{
    char digits[64];
    std::snprintf(digits, sizeof digits, "%.9f", value);
    std::string text = digits;
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
}

}  // namespace

std::string NumberRange::text() const
{
    std::string said = "from " + plain(least) + " to " + plain(most);
    if (*unit) said += std::string(" ") + unit;
    return said;
}

}  // namespace tactiscope::core
