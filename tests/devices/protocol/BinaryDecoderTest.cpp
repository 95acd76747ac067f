// The binary decoder on every awkward cut of the byte stream.
#include "devices/protocol/BinaryDecoder.h"

#include <gtest/gtest.h>

#include <random>

using namespace tactiscope::devices::protocol;

namespace {

std::vector<std::uint8_t> dataFrame(std::uint16_t sequence, std::int16_t first)
{
    return encodeFrame(FrameType::Data, sequence,
                       encodeData({sequence * 1000u,
                                   SampleFormat::Int16,
                                   2,
                                   2,
                                   {double(first), double(-first), double(first + 1), double(-first - 1)}}));
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts)
{
    std::vector<std::uint8_t> all;
    for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    return all;
}

}  // namespace

TEST(BinaryDecoder, AFrameSplitAtEveryPossiblePointStillDecodes)
{
    const auto frame = dataFrame(5, 42);
    for (std::size_t cut = 0; cut <= frame.size(); ++cut) {
        BinaryDecoder decoder;
        std::vector<Frame> out;
        decoder.push(std::span(frame).first(cut), out);
        decoder.push(std::span(frame).subspan(cut), out);
        ASSERT_EQ(out.size(), 1u) << "cut at " << cut;
        EXPECT_EQ(out[0].sequence, 5);
        EXPECT_EQ(parseData(out[0].payload)->raw[0], 42.0);
        EXPECT_EQ(decoder.counters().resyncs, 0u);
    }
}

TEST(BinaryDecoder, SeveralFramesInOneChunkAndByteByByte)
{
    const auto stream = concat({dataFrame(1, 10), dataFrame(2, 20), dataFrame(3, 30)});
    BinaryDecoder whole, bytewise;
    std::vector<Frame> a, b;
    whole.push(stream, a);
    for (std::uint8_t byte : stream) bytewise.push(std::span(&byte, 1), b);
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(a[2].sequence, 3);
    EXPECT_EQ(whole.counters().frames, 3u);
    EXPECT_EQ(whole.counters().bytes, stream.size());
}

TEST(BinaryDecoder, GarbageBeforeBetweenAndInsideFramesIsSkippedAndCounted)
{
    auto corrupted = dataFrame(2, 20);
    corrupted[12] ^= 0xFF;  // a flipped byte inside the payload
    const std::vector<std::uint8_t> noise{0x00, 0xA5, 0x13, 0x5A, 0xA5};
    const auto stream = concat({noise, dataFrame(1, 10), noise, corrupted, dataFrame(3, 30), noise});
    BinaryDecoder decoder;
    std::vector<Frame> out;
    decoder.push(stream, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].sequence, 1);
    EXPECT_EQ(out[1].sequence, 3);  // the frame right after the bad one survives
    EXPECT_EQ(decoder.counters().crcErrors, 1u);
    EXPECT_EQ(decoder.counters().resyncs, 3u);  // before frame 1, before the bad frame, after frame 3
}

TEST(BinaryDecoder, ImpossibleHeadersAreRejectedWithoutWaiting)
{
    // Version 2 and a 60 kB length: neither may make the decoder wait.
    const std::vector<std::uint8_t> badVersion{0xA5, 0x5A, 0x02, 0x02, 0x00, 0x00, 0x00, 0x00};
    const std::vector<std::uint8_t> badLength{0xA5, 0x5A, 0x01, 0x02, 0x60, 0xEA, 0x00, 0x00};
    BinaryDecoder decoder;
    std::vector<Frame> out;
    decoder.push(concat({badVersion, badLength, dataFrame(9, 90)}), out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].sequence, 9);
}

TEST(BinaryDecoder, AFalseSyncInGarbageDoesNotHoldUpTheFramesAfterIt)
{
    // Garbage that looks like the header of a 4000-byte frame, then a real
    // frame: the real one must come out now, not after 4000 more bytes.
    const std::vector<std::uint8_t> falseHeader{0xA5, 0x5A, 0x01, 0x02, 0xA0, 0x0F, 0x00, 0x00, 0x11, 0x22};
    BinaryDecoder decoder;
    std::vector<Frame> out;
    decoder.push(concat({falseHeader, dataFrame(4, 40)}), out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].sequence, 4);
    EXPECT_EQ(decoder.counters().resyncs, 1u);
}

TEST(BinaryDecoder, RandomCorruptionNeverLosesAnUntouchedFrame)
{
    std::mt19937 random(12);
    std::vector<std::uint8_t> stream;
    std::vector<bool> intact;
    for (std::uint16_t s = 0; s < 300; ++s) {
        auto frame = dataFrame(s, static_cast<std::int16_t>(s));
        const bool damage = random() % 5 == 0;
        if (damage) frame[random() % frame.size()] ^= static_cast<std::uint8_t>(1 + random() % 255);
        intact.push_back(!damage);
        if (random() % 4 == 0) stream.push_back(static_cast<std::uint8_t>(random()));  // stray byte
        stream.insert(stream.end(), frame.begin(), frame.end());
    }
    BinaryDecoder decoder;
    std::vector<Frame> out;
    for (std::size_t i = 0; i < stream.size();) {
        const std::size_t n = std::min<std::size_t>(1 + random() % 40, stream.size() - i);
        decoder.push(std::span(stream).subspan(i, n), out);
        i += n;
    }
    std::vector<bool> seen(300, false);
    for (const Frame& f : out) {
        if (f.sequence < 300 && parseData(f.payload)) seen[f.sequence] = true;
    }
    for (std::size_t s = 0; s < 300; ++s) {
        if (intact[s]) {
            EXPECT_TRUE(seen[s]) << "intact frame " << s << " lost";
        }
    }
}
