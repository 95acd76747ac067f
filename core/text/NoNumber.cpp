// spellsNoNumber: the spellings, matched without case.
#include "core/text/NoNumber.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace tactiscope::core::text {

bool spellsNoNumber(std::string_view token)
{
    if (!token.empty() && (token.front() == '-' || token.front() == '+')) token.remove_prefix(1);
    constexpr std::array<std::string_view, 4> kSpellings{"nan", "inf", "infinity", "ovf"};
    return std::ranges::any_of(kSpellings, [token](std::string_view spelling) {
        return std::ranges::equal(token, spelling, [](char a, char b) {
            return std::tolower(static_cast<unsigned char>(a)) == static_cast<unsigned char>(b);
        });
    });
}

}  // namespace tactiscope::core::text
