// The Tactiscope binary wire protocol, version 1 (TSP/1), documented for
// firmware authors in docs/protocol.md. This header holds the frame layout,
// the payload structures and the encoders (used by the emulator, the tests
// and, mirrored in C, by firmware).
//
// Frame (all integers little-endian):
//   0  2  sync 0xA5 0x5A
//   2  1  protocol version (1)
//   3  1  frame type
//   4  2  payload length N (≤ kMaxPayload)
//   6  2  sequence number (per direction, wraps at 65536)
//   8  N  payload
//   8+N 2 CRC-16/CCITT-FALSE over bytes 2 … 8+N−1 (everything after the sync)
#pragma once

#include "core/ChannelDescriptor.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::protocol {

inline constexpr std::uint8_t kSync0 = 0xA5;
inline constexpr std::uint8_t kSync1 = 0x5A;
inline constexpr std::uint8_t kVersion = 1;
inline constexpr std::size_t kHeaderSize = 8;
inline constexpr std::size_t kCrcSize = 2;
inline constexpr std::size_t kMaxPayload = 4096;

enum class FrameType : std::uint8_t {
    Info = 0x01,     // device → host: identity and channels
    Data = 0x02,     // device → host: samples
    Status = 0x03,   // device → host: state or error message
    Command = 0x10,  // host → device
};

enum class SampleFormat : std::uint8_t { Int16 = 0x01, Int32 = 0x02, Float32 = 0x03 };

enum class CommandCode : std::uint8_t {
    Start = 0x01,
    Stop = 0x02,
    SetRate = 0x03,  // argument: u32 sample rate in millihertz
    Tare = 0x04,
    RequestInfo = 0x05,
    // arguments: u8 channel (its place in INFO), u8 1 on / 0 off. The
    // device answers with a STATUS: level ok and "shunt on NAME" / "shunt off
    // NAME", or level error and "shunt: " and why not. A device that does
    // not know the command answers nothing (docs/protocol.md).
    Shunt = 0x06,
};

enum class StatusLevel : std::uint8_t { Ok = 0, Warning = 1, Error = 2 };

struct ChannelInfo {
    core::ChannelDescriptor descriptor;
    float scale = 1.0f;  // SI value = raw · scale + offset
    float offset = 0.0f;
};

struct DeviceInfo {
    std::string vendor, model, serialNumber, firmwareVersion;
    std::uint32_t sampleRate_mhz = 0;  // millihertz: 500 Hz is 500000
    std::vector<ChannelInfo> channels;
};

struct DataPayload {
    std::uint32_t timestamp_us = 0;  // device clock at the first sample; wraps
    SampleFormat format = SampleFormat::Int16;
    std::uint8_t channelCount = 0;
    std::uint16_t samplesPerChannel = 0;
    std::vector<double> raw;  // sample-major: s0c0 s0c1 … s1c0 …, as integers or floats
};

struct StatusPayload {
    StatusLevel level = StatusLevel::Ok;
    std::string message;
};

struct CommandPayload {
    CommandCode code = CommandCode::Start;
    std::uint32_t argument = 0;  // SetRate only
    std::uint8_t channel = 0;    // Shunt only
    bool on = false;             // Shunt only
};

// A frame as it left the decoder: checked CRC, parsed header.
struct Frame {
    FrameType type = FrameType::Data;
    std::uint16_t sequence = 0;
    std::vector<std::uint8_t> payload;
};

// Complete frames, ready to send.
std::vector<std::uint8_t> encodeFrame(FrameType type, std::uint16_t sequence, const std::vector<std::uint8_t>& payload);
std::vector<std::uint8_t> encodeInfo(const DeviceInfo& info);
std::vector<std::uint8_t> encodeData(const DataPayload& data);
std::vector<std::uint8_t> encodeStatus(const StatusPayload& status);
std::vector<std::uint8_t> encodeCommand(const CommandPayload& command);

// Payload parsers: nothing on a malformed payload (the frame's CRC was fine,
// so that is a firmware bug the caller counts and reports).
std::optional<DeviceInfo> parseInfo(const std::vector<std::uint8_t>& payload);
std::optional<DataPayload> parseData(const std::vector<std::uint8_t>& payload);
std::optional<StatusPayload> parseStatus(const std::vector<std::uint8_t>& payload);
std::optional<CommandPayload> parseCommand(const std::vector<std::uint8_t>& payload);

}  // namespace tactiscope::devices::protocol
