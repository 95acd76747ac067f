// TSP/1: CRC check value, payload round trips, and the worked examples of
// docs/protocol.md byte for byte (so the document cannot drift).
#include "devices/protocol/BinaryProtocol.h"

#include "devices/protocol/Crc16.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace tactiscope::devices::protocol;
using tactiscope::core::ChannelKind;

namespace {

std::string hex(const std::vector<std::uint8_t>& bytes)
{
    std::string text;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        char byte[4];
        std::snprintf(byte, sizeof byte, "%02X", bytes[i]);
        text += (i ? " " : "") + std::string(byte);
    }
    return text;
}

}  // namespace

TEST(BinaryProtocol, CrcHasTheStandardCheckValue)
{
    const std::string check = "123456789";
    EXPECT_EQ(crc16Ccitt(std::span(reinterpret_cast<const std::uint8_t*>(check.data()), check.size())), 0x29B1);
}

TEST(BinaryProtocol, PayloadsRoundTrip)
{
    DeviceInfo info{
        "Acme",   "Probe-2",
        "SN0042", "1.3.0",
        500000,   {{{"a", "", ChannelKind::Strain}, 1e-6f, 0.0f}, {{"b", "", ChannelKind::Strain}, 1e-6f, 0.5f}}};
    const auto parsedInfo = parseInfo(encodeInfo(info));
    ASSERT_TRUE(parsedInfo.has_value());
    EXPECT_EQ(parsedInfo->serialNumber, "SN0042");
    EXPECT_EQ(parsedInfo->sampleRate_mhz, 500000u);
    EXPECT_EQ(parsedInfo->channels[1].descriptor, info.channels[1].descriptor);
    EXPECT_EQ(parsedInfo->channels[1].offset, 0.5f);

    for (SampleFormat format : {SampleFormat::Int16, SampleFormat::Int32, SampleFormat::Float32}) {
        DataPayload data{123456789u, format, 2, 3, {1, -2, 300, -32768, 32767, 7}};
        const auto parsed = parseData(encodeData(data));
        ASSERT_TRUE(parsed.has_value());
        EXPECT_EQ(parsed->raw, data.raw);
        EXPECT_EQ(parsed->timestamp_us, 123456789u);
    }
    EXPECT_EQ(parseStatus(encodeStatus({StatusLevel::Error, "bridge open"}))->message, "bridge open");
    const auto command = parseCommand(encodeCommand({CommandCode::SetRate, 2000000}));
    EXPECT_EQ(command->code, CommandCode::SetRate);
    EXPECT_EQ(command->argument, 2000000u);
}

TEST(BinaryProtocol, MalformedPayloadsAreRefused)
{
    EXPECT_FALSE(parseData({1, 2, 3}).has_value());
    auto data = encodeData({0, SampleFormat::Int16, 1, 2, {1, 2}});
    data.pop_back();  // one byte short
    EXPECT_FALSE(parseData(data).has_value());
    EXPECT_FALSE(parseInfo({2}).has_value());  // unknown info layout
    EXPECT_FALSE(parseCommand({9}).has_value());
}

TEST(BinaryProtocol, TheDocumentedExamplesAreWhatTheEncoderWrites)
{
    // docs/protocol.md, "Worked examples". The CRC bytes were computed with
    // an independent bit-by-bit CRC-16/CCITT-FALSE, not with crc16Ccitt().
    EXPECT_EQ(
        hex(encodeFrame(FrameType::Data, 7, encodeData({1000, SampleFormat::Int16, 2, 2, {100, -100, 101, -99}}))),
        "A5 5A 01 02 10 00 07 00 E8 03 00 00 02 01 02 00 64 00 9C FF 65 00 9D FF 0E 6A");
    EXPECT_EQ(hex(encodeFrame(FrameType::Command, 0, encodeCommand({CommandCode::Start, 0}))),
              "A5 5A 01 10 01 00 00 00 01 5B E9");
    EXPECT_EQ(hex(encodeFrame(FrameType::Command, 1, encodeCommand({CommandCode::SetRate, 2000000}))),
              "A5 5A 01 10 05 00 01 00 03 80 84 1E 00 71 A3");
    EXPECT_EQ(hex(encodeFrame(FrameType::Status, 3, encodeStatus({StatusLevel::Warning, "hot"}))),
              "A5 5A 01 03 05 00 03 00 01 03 68 6F 74 87 34");
    EXPECT_EQ(
        hex(encodeFrame(FrameType::Info, 0,
                        encodeInfo({"A", "P", "S1", "1.0", 500000, {{{"a", "", ChannelKind::Strain}, 1e-6f, 0.0f}}}))),
        "A5 5A 01 01 1D 00 00 00 01 01 41 01 50 02 53 31 03 31 2E 30 20 A1 07 00 01 01 61 00 00 BD 37 86 35 00 00 00 "
        "00 "
        "E6 E9");
}
