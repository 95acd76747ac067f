// MD5 against the test suite of RFC 1321 (appendix A.5), and a message fed
// in uneven pieces digesting as when fed whole.
#include "core/text/Md5.h"

#include <gtest/gtest.h>

#include <string>

using tactiscope::core::text::Md5;

namespace {

std::string md5Of(std::string_view text)
{
    Md5 md5;
    md5.add(text);
    return md5.hex();
}

}  // namespace

TEST(Md5, GivesTheDigestsOfRfc1321)
{
    EXPECT_EQ(md5Of(""), "d41d8cd98f00b204e9800998ecf8427e");
    EXPECT_EQ(md5Of("a"), "0cc175b9c0f1b6a831c399e269772661");
    EXPECT_EQ(md5Of("abc"), "900150983cd24fb0d6963f7d28e17f72");
    EXPECT_EQ(md5Of("message digest"), "f96b697d7cb7938d525a2f31aaf161d0");
    EXPECT_EQ(md5Of("abcdefghijklmnopqrstuvwxyz"), "c3fcd3d76192e4007dfb496cca67e13b");
    EXPECT_EQ(md5Of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"),
              "d174ab98d277d9f5a5611c2c9f419d9f");
    EXPECT_EQ(md5Of("12345678901234567890123456789012345678901234567890123456789012345678901234567890"),
              "57edf4a22be3c955ac49da2e2107b67a");
}

TEST(Md5, PiecesDigestAsTheWhole)
{
    std::string message;
    for (int i = 0; i < 1000; ++i) message += static_cast<char>(i * 7);
    Md5 pieces;
    for (std::size_t at = 0, step = 1; at < message.size(); at += step, step = step * 3 % 97 + 1)
        pieces.add(std::string_view(message).substr(at, step));
    EXPECT_EQ(pieces.hex(), md5Of(message));
}
