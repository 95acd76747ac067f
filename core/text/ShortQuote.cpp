// ShortQuote: cut at a character's boundary, never inside a UTF-8 sequence.
#include "core/text/ShortQuote.h"

#include <optional>

namespace tactiscope::core::text {
namespace {

struct Cut {
    std::string_view head;
    std::optional<std::size_t> characters;  // when cut: how many there were
};

Cut cutOf(std::string_view value)
{
    std::size_t characters = 0, end = value.size();
    for (std::size_t i = 0; i < value.size(); ++i) {
        if ((static_cast<unsigned char>(value[i]) & 0xC0) == 0x80) continue;  // a continuation byte
        if (characters == kMostQuoted) end = i;
        ++characters;
    }
    if (characters <= kMostQuoted) return {value, std::nullopt};
    return {value.substr(0, end), characters};
}

std::string lengthOf(std::size_t characters)
{
    return " (" + std::to_string(characters) + " characters)";
}

}  // namespace

std::string shortened(std::string_view value)
{
    const Cut cut = cutOf(value);
    return std::string(cut.head) + (cut.characters ? "…" + lengthOf(*cut.characters) : "");
}

std::string quoteShort(std::string_view value)
{
    const Cut cut = cutOf(value);
    return "'" + std::string(cut.head) + (cut.characters ? "…'" + lengthOf(*cut.characters) : "'");
}

}  // namespace tactiscope::core::text
