// A value repeated in a message is cut at 40 characters (not bytes), never
// inside a UTF-8 sequence, and says its length when cut.
#include "core/text/ShortQuote.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>

using tactiscope::core::text::quoteShort;
using tactiscope::core::text::shortened;

namespace {

// Texts joined (GCC 12 warns falsely of a bound on "'" + s + "…" chains).
std::string joined(std::initializer_list<std::string_view> parts)
{
    std::string text;
    for (const auto part : parts) text.append(part);
    return text;
}

}  // namespace

TEST(ShortQuote, AShortValueIsWholeALongOneItsFirstFortyCharactersAndItsLength)
{
    EXPECT_EQ(quoteShort("a>0.5"), "'a>0.5'");
    EXPECT_EQ(shortened("a>0.5"), "a>0.5");
    const std::string forty(40, 'x');
    EXPECT_EQ(quoteShort(forty), joined({"'", forty, "'"}));
    EXPECT_EQ(quoteShort(joined({forty, "y"})), joined({"'", forty, "…' (41 characters)"}));
    EXPECT_EQ(shortened(std::string(100000, 'z')), joined({std::string(40, 'z'), "… (100000 characters)"}));
    // "µ" is two bytes, one character: forty of them are whole, and the
    // cut of more falls between characters.
    std::string micro;
    for (int i = 0; i < 40; ++i) micro += "µ";
    EXPECT_EQ(quoteShort(micro), joined({"'", micro, "'"}));
    EXPECT_EQ(quoteShort(joined({micro, "µµ"})), joined({"'", micro, "…' (42 characters)"}));
    EXPECT_EQ(quoteShort(""), "''");
}
