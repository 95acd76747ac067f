// The Serial-Plotter text protocol.
#include "devices/protocol/TextDecoder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace tactiscope::devices::protocol;

namespace {

std::vector<TextSample> decode(TextDecoder& decoder, const std::string& text, double t = 0.0)
{
    std::vector<TextSample> out;
    decoder.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), t, out);
    return out;
}

}  // namespace

TEST(TextDecoder, ReadsCommaSpaceAndTabSeparatedLines)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "1,2,3\n4 5 6\r\n7\t8\t9\n10, 11 ,12\n");
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[1].values, (std::vector<double>{4, 5, 6}));
    EXPECT_EQ(out[3].values, (std::vector<double>{10, 11, 12}));
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"ch1", "ch2", "ch3"}));
}

TEST(TextDecoder, NamesChannelsFromLabels)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "high:512 low:-3.25e1\nhigh:510 low:-31\n");
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"high", "low"}));
    EXPECT_EQ(out[0].values[1], -32.5);
}

TEST(TextDecoder, LinesThatDoNotParseAreCountedHolesOnceTheChannelsAreKnown)
{
    TextDecoder decoder;
    const std::string longLine(TextDecoder::kMaxLine + 10, '1');
    const auto out = decode(decoder, "1,2\n3,4\nhello,3\n4\n5,6,7\n\n\r\n" + longLine + "\n8,-3.4e38\n");
    // "1,2", "3,4", four holes (word, too few, too many, overlong),
    // "8,-3.4e38"; the empty lines are nothing.
    ASSERT_EQ(out.size(), 7u);
    EXPECT_EQ(out[1].values, (std::vector<double>{3, 4}));
    for (std::size_t i = 2; i < 6; ++i) EXPECT_TRUE(out[i].values.empty()) << i;
    EXPECT_EQ(out[6].values, (std::vector<double>{8, -3.4e38}));
    EXPECT_EQ(decoder.counters().linesSkipped, 4u);
    EXPECT_EQ(decoder.counters().frames, 3u);
}

// Before, "3.5,nan" made the whole line a hole and the 3.5 was lost.
TEST(TextDecoder, AValueThatIsNoNumberIsAHoleInItsChannelAlone)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "1,2\n3,4\n3.5,nan\n-inf,5\n1e308,6\n7,ovf\nNaN,+inf\n8,Infinity\n"
                                     "a:1 b:2\n9,10\n");
    ASSERT_EQ(out.size(), 10u);  // "a:1 b:2" has other channels, and the line after it not: a hole
    const auto holeAt = [&](std::size_t sample, std::size_t channel) {
        return std::isnan(out[sample].values.at(channel));
    };
    EXPECT_EQ(out[2].values[0], 3.5);
    EXPECT_TRUE(holeAt(2, 1));
    EXPECT_TRUE(holeAt(3, 0));
    EXPECT_EQ(out[3].values[1], 5.0);
    EXPECT_TRUE(holeAt(4, 0));  // beyond what a stored sample holds
    EXPECT_EQ(out[4].values[1], 6.0);
    EXPECT_EQ(out[5].values[0], 7.0);
    EXPECT_TRUE(holeAt(5, 1));
    EXPECT_TRUE(holeAt(6, 0) && holeAt(6, 1));
    EXPECT_TRUE(holeAt(7, 1));
    EXPECT_TRUE(out[8].values.empty());
    EXPECT_EQ(decoder.counters().valueHoles, 7u);
    EXPECT_EQ(decoder.counters().frames, 9u);
    EXPECT_EQ(decoder.counters().linesSkipped, 1u);
}

TEST(TextDecoder, AFragmentFirstDoesNotFixTheChannels)
{
    // The port opened in the middle of "1.25,2.5": only "2.5" arrived whole.
    TextDecoder decoder;
    const auto out = decode(decoder, "2.5\n3,4\n5,6\n7,8\n");
    ASSERT_EQ(out.size(), 3u);  // before: one channel, and every later line skipped
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"ch1", "ch2"}));
    EXPECT_EQ(out[0].values, (std::vector<double>{3, 4}));
    EXPECT_EQ(decoder.counters().linesSkipped, 1u);
}

TEST(TextDecoder, LinesSplitAcrossChunksKeepTheTimeOfTheirEnd)
{
    TextDecoder decoder;
    EXPECT_TRUE(decode(decoder, "1.5,2", 1.0).empty());
    const auto out = decode(decoder, ".5\n3,4\n", 1.1);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].values, (std::vector<double>{1.5, 2.5}));
    EXPECT_EQ(out[0].hostTime_s, 1.1);
}

// A board's log between its samples ("Sensor OK") is no sample lost: the
// lines after it keep their time. A line with a number in it that does not
// read (a garbled sample) still is one.
TEST(TextDecoder, ALineWithNoNumberIsTheBoardsLogNotALostSample)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "1,2\n3,4\nSensor OK\n#debug: reset\n5,6\n7,x\n9,10\n");
    ASSERT_EQ(out.size(), 5u);
    EXPECT_EQ(out[2].values, (std::vector<double>{5, 6}));
    EXPECT_TRUE(out[3].values.empty());
    EXPECT_EQ(out[4].values, (std::vector<double>{9, 10}));
    EXPECT_EQ(decoder.counters().linesSkipped, 3u);
}

// A board that prints numbers is waited for (PortSource) however slowly it
// prints: one line of numbers is enough to know it does; words are not.
TEST(TextDecoder, OneLineOfNumbersSaysTheBoardPrintsThem)
{
    TextDecoder decoder;
    decode(decoder, "hello world\n");
    EXPECT_FALSE(decoder.heardNumbers());
    decode(decoder, "1.5,2\n");
    EXPECT_TRUE(decoder.heardNumbers());
    TextDecoder teleplot;
    decode(teleplot, ">temp:21.5\n");
    EXPECT_TRUE(teleplot.heardNumbers());
}

namespace {

bool isHole(double value)
{
    return std::isnan(value);
}

}  // namespace

// Before, a board that began to print another channel, or renamed one,
// turned every later line into a hole.
TEST(TextDecoder, ANewLayoutContinuesWithItsChannelsAfterTheOthers)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "a:1 b:2\na:3 b:4\na:5 c:6\nc:8 a:7\na:9 c:10\n");
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"a", "b", "c"}));
    ASSERT_EQ(out.size(), 5u);
    EXPECT_EQ(out[1].values, (std::vector<double>{3, 4}));
    // c is a channel of its own from the first line that printed it; b,
    // renamed, a hole from there.
    ASSERT_EQ(out[2].values.size(), 3u);
    EXPECT_EQ(out[2].values[0], 5.0);
    EXPECT_TRUE(isHole(out[2].values[1]));
    EXPECT_EQ(out[2].values[2], 6.0);
    EXPECT_EQ(out[3].values[0], 7.0);
    EXPECT_EQ(out[3].values[2], 8.0);  // by label, in any order
    EXPECT_EQ(out[2].layoutChange, "the board's channels changed: c appeared (holes before the first value); b is no "
                                   "longer printed (holes from here)");
    EXPECT_FALSE(out[3].layoutChange);
    EXPECT_EQ(decoder.counters().frames, 5u);
    EXPECT_EQ(decoder.counters().linesSkipped, 0u);
}

TEST(TextDecoder, UnlabelledValuesThatBecomeMoreAreNewChannelsAndFewerAreHoles)
{
    TextDecoder decoder;
    const auto out = decode(decoder, "1\n2\n3,30\n4,40\n5\n6\n");
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"ch1", "ch2"}));
    ASSERT_EQ(out.size(), 6u);
    EXPECT_EQ(out[1].values, (std::vector<double>{2}));
    EXPECT_EQ(out[2].values, (std::vector<double>{3, 30}));
    EXPECT_EQ(out[2].layoutChange, "the board's channels changed: ch2 appeared (holes before the first value)");
    EXPECT_EQ(out[4].values[0], 5.0);
    EXPECT_TRUE(isHole(out[4].values[1]));
    EXPECT_EQ(out[4].layoutChange, "the board's channels changed: ch2 is no longer printed (holes from here)");
}

TEST(TextDecoder, OneLineOfOtherLabelsIsAHoleNotANewChannel)
{
    TextDecoder decoder;
    // A line garbled on the way ("a:5 x:6"), between lines of the layout.
    const auto out = decode(decoder, "a:1 b:2\na:3 b:4\na:5 x:6\na:7 b:8\n");
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"a", "b"}));
    ASSERT_EQ(out.size(), 4u);
    EXPECT_TRUE(out[2].values.empty());
    EXPECT_EQ(out[3].values, (std::vector<double>{7, 8}));
    EXPECT_EQ(decoder.counters().linesSkipped, 1u);
}

TEST(TextDecoder, ATeleplotVariableIsAChannelFromItsFirstValueAndAHoleWhereAnInstantLacksIt)
{
    TextDecoder decoder;
    const auto out = decode(decoder, ">a:1\n>b:2\n>a:3\n>b:4\n>a:5\n>b:6\n>c:7\n>a:8\n>c:9\n>a:10\n");
    EXPECT_EQ(decoder.channelNames(), (std::vector<std::string>{"a", "b", "c"}));
    // Instants: (1,2) (3,4) (5,6,7) (8,9); the last is gathering.
    ASSERT_EQ(out.size(), 4u);
    ASSERT_EQ(out[2].values.size(), 3u);
    EXPECT_EQ(out[2].values, (std::vector<double>{5, 6, 7}));
    EXPECT_EQ(out[2].layoutChange, "the board's channels changed: c appeared (holes before the first value)");
    EXPECT_EQ(out[3].values[0], 8.0);
    EXPECT_TRUE(isHole(out[3].values[1]));
    EXPECT_EQ(out[3].values[2], 9.0);
}
