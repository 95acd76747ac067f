// Frames and lines into SampleBlocks: scaling, gaps, clock wrap, rates.
#include "devices/protocol/BinaryStream.h"
#include "devices/protocol/TextStream.h"

#include <gtest/gtest.h>

#include <string>

using namespace tactiscope::devices::protocol;
using tactiscope::core::ChannelKind;

namespace {

std::vector<std::uint8_t> data(std::uint16_t sequence, std::uint32_t timestamp_us, std::int16_t value,
                               std::uint16_t samples = 4)
{
    DataPayload d{timestamp_us, SampleFormat::Int16, 2, samples, {}};
    for (std::uint16_t s = 0; s < samples; ++s) {
        d.raw.push_back(value + s);
        d.raw.push_back(-(value + s));
    }
    return encodeFrame(FrameType::Data, sequence, encodeData(d));
}

std::vector<std::uint8_t> info()
{
    return encodeFrame(
        FrameType::Info, 0,
        encodeInfo({"Acme",
                    "P2",
                    "SN9",
                    "1.0",
                    1000000,  // 1 kHz
                    {{{"a", "", ChannelKind::Strain}, 1e-6f, 0.0f}, {{"b", "", ChannelKind::Strain}, 2e-6f, 1e-5f}}}));
}

}  // namespace

TEST(BinaryStream, ScalesSamplesWithTheInfoFramesChannels)
{
    BinaryStream stream;
    StreamOutput out;
    auto bytes = info();
    const auto frame = data(0, 5000, 100);
    bytes.insert(bytes.end(), frame.begin(), frame.end());
    stream.push(bytes, out);
    EXPECT_TRUE(out.infoChanged);
    ASSERT_EQ(out.blocks.size(), 1u);
    const auto& block = out.blocks[0];
    EXPECT_DOUBLE_EQ(block.dt_s(), 0.001);
    // Scale and offset travel as float32: expect exactly what they encode.
    EXPECT_DOUBLE_EQ(block.value(0, 2), 102 * static_cast<double>(1e-6f));
    EXPECT_DOUBLE_EQ(block.value(1, 2), -102 * static_cast<double>(2e-6f) + static_cast<double>(1e-5f));
    EXPECT_EQ(stream.channels()[1].name, "b");
    EXPECT_EQ(stream.info()->serialNumber, "SN9");
}

TEST(BinaryStream, CountsSamplesLostToSequenceGapsAndLeavesAGapInTheIndex)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), out);
    stream.push(data(10, 0, 0), out);
    stream.push(data(11, 4000, 4), out);
    stream.push(data(14, 16000, 16), out);  // frames 12 and 13 lost
    ASSERT_EQ(out.blocks.size(), 3u);
    EXPECT_EQ(stream.counters().samplesLost, 8u);
    EXPECT_EQ(out.blocks[2].firstSampleIndex(), 16u);
    EXPECT_EQ(out.blocks[2].samplesLostAfter(out.blocks[1].endSampleIndex()), 8u);
    EXPECT_DOUBLE_EQ(out.blocks[2].t0_s(), 0.016);
}

TEST(BinaryStream, UnwrapsTheDeviceClock)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), out);
    stream.push(data(0, 0xFFFFF000u, 0), out);  // 4096 µs before the wrap
    stream.push(data(1, 0x00000FA0u, 4), out);  // 4000 µs after it
    ASSERT_EQ(out.blocks.size(), 2u);
    EXPECT_NEAR(out.blocks[1].t0_s() - out.blocks[0].t0_s(), (4096 + 4000) * 1e-6, 1e-12);
}

TEST(BinaryStream, WithoutInfoTheRateComesFromTheTimestamps)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(data(0, 1000, 7), out);
    EXPECT_TRUE(out.blocks.empty());      // the first frame waits for the interval
    stream.push(data(1, 3000, 11), out);  // 4 samples in 2000 µs: 2 kHz
    ASSERT_EQ(out.blocks.size(), 2u);
    EXPECT_DOUBLE_EQ(*stream.sampleRate_hz(), 2000.0);
    EXPECT_EQ(stream.channels()[0].name, "ch1");
    EXPECT_EQ(out.blocks[0].value(0, 0), 7.0);  // unscaled
    EXPECT_EQ(out.blocks[1].firstSampleIndex(), 4u);
}

TEST(BinaryStream, PassesStatusMessagesAndCountsMalformedPayloads)
{
    BinaryStream stream;
    StreamOutput out;
    auto bytes = encodeFrame(FrameType::Status, 0, encodeStatus({StatusLevel::Error, "bridge open"}));
    const auto bad = encodeFrame(FrameType::Data, 1, {1, 2, 3});
    bytes.insert(bytes.end(), bad.begin(), bad.end());
    stream.push(bytes, out);
    ASSERT_EQ(out.statuses.size(), 1u);
    EXPECT_EQ(out.statuses[0].message, "bridge open");
    EXPECT_EQ(stream.counters().malformedPayloads, 1u);
}

TEST(TextStream, UsesTheGivenRate)
{
    TextStream stream(250.0);
    std::vector<tactiscope::core::SampleBlock> out;
    const std::string text = "a:1 b:2\na:3 b:4\n";
    stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0.0, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_DOUBLE_EQ(out[0].dt_s(), 0.004);
    EXPECT_EQ(out[0].value(1, 1), 4.0);
    EXPECT_EQ(stream.channels()[1].name, "b");
}

TEST(TextStream, EstimatesTheRateFromTwoSecondsOfArrivals)
{
    TextStream stream;
    std::vector<tactiscope::core::SampleBlock> out;
    // 100 lines per second, arriving in bursts of five every 50 ms.
    for (int burst = 0; burst <= 44; ++burst) {
        std::string text;
        for (int i = 0; i < 5; ++i) text += std::to_string(burst * 5 + i) + "\n";
        stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), burst * 0.05, out);
    }
    ASSERT_TRUE(stream.sampleRate_hz().has_value());
    EXPECT_NEAR(*stream.sampleRate_hz(), 100.0, 3.0);
    ASSERT_FALSE(out.empty());
    EXPECT_EQ(out[0].value(0, 0), 0.0);  // held lines come out first, in order
}
