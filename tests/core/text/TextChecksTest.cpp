// Text a store may hold: UTF-8 (RFC 3629's table, checked byte by byte),
// no NUL; a Latin-1 header turned into UTF-8; uuids that are uuids.
#include "core/text/TextChecks.h"

#include <gtest/gtest.h>

using namespace tactiscope::core::text;

TEST(TextChecks, ValidUtf8PassesAndEveryKindOfBadByteIsNamed)
{
    EXPECT_FALSE(textProblem(""));
    EXPECT_FALSE(textProblem("strain [µε] 中 😀"));
    EXPECT_EQ(textProblem("a\xB5"
                          "b"),
              "byte 0xB5 at 1 is not UTF-8");                                   // Latin-1 µ
    EXPECT_EQ(textProblem("x\xC0\xAF"), "byte 0xC0 at 1 is not UTF-8");         // an overlong '/'
    EXPECT_EQ(textProblem("\xED\xA0\x80"), "byte 0xA0 at 1 is not UTF-8");      // a surrogate
    EXPECT_EQ(textProblem("\xF4\x90\x80\x80"), "byte 0x90 at 1 is not UTF-8");  // above U+10FFFF
    EXPECT_EQ(textProblem("ok\xE4\xB8"), "byte 0xE4 at 2 starts a character the text cuts off");
    EXPECT_EQ(textProblem(std::string_view("door\0 17", 8)), "a NUL character at 4");
}

TEST(TextChecks, Latin1BecomesTheSameCharactersInUtf8)
{
    EXPECT_EQ(latin1ToUtf8("a [\xB5"
                           "e]"),
              "a [µe]");
    EXPECT_EQ(latin1ToUtf8("\xE9t\xE9 \xFF"), "été ÿ");
    EXPECT_FALSE(textProblem(latin1ToUtf8("\x80\x81\xFE")));
}

TEST(TextChecks, AUuidIsEightFourFourFourTwelveHexDigits)
{
    EXPECT_TRUE(isUuid("3f2b8c1e-9d4a-4c7e-8b1a-0123456789ab"));
    EXPECT_TRUE(isUuid("3F2B8C1E-9D4A-4C7E-8B1A-0123456789AB"));
    EXPECT_FALSE(isUuid("3f2b8c1e-9d4a-4c7e-8b1a-0123456789a"));
    EXPECT_FALSE(isUuid("3f2b8c1e-9d4a-4c7e-8b1a-0123456789a\""));
    EXPECT_FALSE(isUuid("3f2b8c1e+9d4a-4c7e-8b1a-0123456789ab"));
    EXPECT_FALSE(isUuid("x\"y\\z"));
}
