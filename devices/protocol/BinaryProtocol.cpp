// TSP/1 encoding and payload parsing, little-endian throughout.
#include "devices/protocol/BinaryProtocol.h"

#include "devices/protocol/Crc16.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace tactiscope::devices::protocol {
namespace {

class Writer {
public:
    void u8(std::uint8_t v) { m_bytes.push_back(v); }
    void u16(std::uint16_t v)
    {
        u8(static_cast<std::uint8_t>(v & 0xFF));
        u8(static_cast<std::uint8_t>(v >> 8));
    }
    void u32(std::uint32_t v)
    {
        u16(static_cast<std::uint16_t>(v & 0xFFFF));
        u16(static_cast<std::uint16_t>(v >> 16));
    }
    void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void str(const std::string& s)
    {
        if (s.size() > 255) throw std::invalid_argument("protocol strings are at most 255 bytes");
        u8(static_cast<std::uint8_t>(s.size()));
        m_bytes.insert(m_bytes.end(), s.begin(), s.end());
    }
    std::vector<std::uint8_t>& bytes() { return m_bytes; }

private:
    std::vector<std::uint8_t> m_bytes;
};

// Bounds-checked reader: any read past the end makes ok() false.
class Reader {
public:
    explicit Reader(const std::vector<std::uint8_t>& bytes)
        : m_bytes(bytes)
    {
    }
    bool ok() const { return m_ok; }
    bool atEnd() const { return m_pos == m_bytes.size(); }
    std::uint8_t u8()
    {
        if (m_pos + 1 > m_bytes.size()) return fail<std::uint8_t>();
        return m_bytes[m_pos++];
    }
    std::uint16_t u16()
    {
        const std::uint16_t lo = u8();
        return static_cast<std::uint16_t>(lo | (u8() << 8));
    }
    std::uint32_t u32()
    {
        const std::uint32_t lo = u16();
        return lo | (static_cast<std::uint32_t>(u16()) << 16);
    }
    float f32() { return std::bit_cast<float>(u32()); }
    std::string str()
    {
        const std::size_t n = u8();
        if (!m_ok || m_pos + n > m_bytes.size()) return fail<std::string>();
        std::string s(m_bytes.begin() + static_cast<std::ptrdiff_t>(m_pos),
                      m_bytes.begin() + static_cast<std::ptrdiff_t>(m_pos + n));
        m_pos += n;
        return s;
    }

private:
    template <typename T>
    T fail()
    {
        m_ok = false;
        m_pos = m_bytes.size();
        return T{};
    }

    const std::vector<std::uint8_t>& m_bytes;
    std::size_t m_pos = 0;
    bool m_ok = true;
};

std::size_t sampleSize(SampleFormat format)
{
    return format == SampleFormat::Int16 ? 2 : 4;
}

}  // namespace

std::vector<std::uint8_t> encodeFrame(FrameType type, std::uint16_t sequence, const std::vector<std::uint8_t>& payload)
{
    if (payload.size() > kMaxPayload) throw std::invalid_argument("payload exceeds the protocol's maximum");
    Writer w;
    w.u8(kSync0);
    w.u8(kSync1);
    w.u8(kVersion);
    w.u8(static_cast<std::uint8_t>(type));
    w.u16(static_cast<std::uint16_t>(payload.size()));
    w.u16(sequence);
    auto& bytes = w.bytes();
    bytes.insert(bytes.end(), payload.begin(), payload.end());
    w.u16(crc16Ccitt(std::span(bytes).subspan(2)));
    return std::move(bytes);
}

std::vector<std::uint8_t> encodeInfo(const DeviceInfo& info)
{
    Writer w;
    w.u8(1);  // info layout version
    w.str(info.vendor);
    w.str(info.model);
    w.str(info.serialNumber);
    w.str(info.firmwareVersion);
    w.u32(info.sampleRate_mhz);
    w.u8(static_cast<std::uint8_t>(info.channels.size()));
    for (const auto& c : info.channels) {
        w.str(c.descriptor.name);
        w.str(c.descriptor.unit);
        w.u8(static_cast<std::uint8_t>(c.descriptor.kind));
        w.f32(c.scale);
        w.f32(c.offset);
    }
    return std::move(w.bytes());
}

std::vector<std::uint8_t> encodeData(const DataPayload& d)
{
    if (d.raw.size() != static_cast<std::size_t>(d.channelCount) * d.samplesPerChannel)
        throw std::invalid_argument("data payload: sample count does not match the shape");
    Writer w;
    w.u32(d.timestamp_us);
    w.u8(d.channelCount);
    w.u8(static_cast<std::uint8_t>(d.format));
    w.u16(d.samplesPerChannel);
    for (double v : d.raw) {
        switch (d.format) {
        case SampleFormat::Int16:
            w.u16(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(v))));
            break;
        case SampleFormat::Int32:
            w.u32(static_cast<std::uint32_t>(static_cast<std::int32_t>(std::llround(v))));
            break;
        case SampleFormat::Float32:
            w.f32(static_cast<float>(v));
            break;
        }
    }
    return std::move(w.bytes());
}

std::vector<std::uint8_t> encodeStatus(const StatusPayload& status)
{
    Writer w;
    w.u8(static_cast<std::uint8_t>(status.level));
    w.str(status.message);
    return std::move(w.bytes());
}

std::vector<std::uint8_t> encodeCommand(const CommandPayload& command)
{
    Writer w;
    w.u8(static_cast<std::uint8_t>(command.code));
    if (command.code == CommandCode::SetRate) w.u32(command.argument);
    if (command.code == CommandCode::Shunt) {
        w.u8(command.channel);
        w.u8(command.on ? 1 : 0);
    }
    return std::move(w.bytes());
}

std::optional<DeviceInfo> parseInfo(const std::vector<std::uint8_t>& payload)
{
    Reader r(payload);
    if (r.u8() != 1) return std::nullopt;
    DeviceInfo info;
    info.vendor = r.str();
    info.model = r.str();
    info.serialNumber = r.str();
    info.firmwareVersion = r.str();
    info.sampleRate_mhz = r.u32();
    const std::size_t channels = r.u8();
    for (std::size_t i = 0; i < channels && r.ok(); ++i) {
        ChannelInfo c;
        c.descriptor.name = r.str();
        c.descriptor.unit = r.str();
        const std::uint8_t kind = r.u8();
        // A kind this host does not know (a newer probe's) is "other": recorded as it comes.
        c.descriptor.kind = kind <= static_cast<std::uint8_t>(core::ChannelKind::Decision)
                                ? static_cast<core::ChannelKind>(kind)
                                : core::ChannelKind::Other;
        c.scale = r.f32();
        c.offset = r.f32();
        info.channels.push_back(c);
    }
    if (!r.ok() || !r.atEnd()) return std::nullopt;
    return info;
}

std::optional<DataPayload> parseData(const std::vector<std::uint8_t>& payload)
{
    Reader r(payload);
    DataPayload d;
    d.timestamp_us = r.u32();
    d.channelCount = r.u8();
    const std::uint8_t format = r.u8();
    d.samplesPerChannel = r.u16();
    if (!r.ok() || format < 1 || format > 3 || d.channelCount == 0) return std::nullopt;
    d.format = static_cast<SampleFormat>(format);
    const std::size_t values = static_cast<std::size_t>(d.channelCount) * d.samplesPerChannel;
    if (payload.size() != 8 + values * sampleSize(d.format)) return std::nullopt;
    d.raw.reserve(values);
    for (std::size_t i = 0; i < values; ++i) {
        switch (d.format) {
        case SampleFormat::Int16:
            d.raw.push_back(static_cast<std::int16_t>(r.u16()));
            break;
        case SampleFormat::Int32:
            d.raw.push_back(static_cast<std::int32_t>(r.u32()));
            break;
        case SampleFormat::Float32:
            d.raw.push_back(r.f32());
            break;
        }
    }
    return d;
}

std::optional<StatusPayload> parseStatus(const std::vector<std::uint8_t>& payload)
{
    Reader r(payload);
    const std::uint8_t level = r.u8();
    StatusPayload s{static_cast<StatusLevel>(level > 2 ? 2 : level), r.str()};
    if (!r.ok() || !r.atEnd()) return std::nullopt;
    return s;
}

std::optional<CommandPayload> parseCommand(const std::vector<std::uint8_t>& payload)
{
    Reader r(payload);
    const std::uint8_t code = r.u8();
    if (!r.ok() || code < 1 || code > 6) return std::nullopt;
    CommandPayload c{static_cast<CommandCode>(code), 0};
    if (c.code == CommandCode::SetRate) c.argument = r.u32();
    if (c.code == CommandCode::Shunt) {
        c.channel = r.u8();
        const std::uint8_t state = r.u8();
        if (state > 1) return std::nullopt;
        c.on = state == 1;
    }
    if (!r.ok() || !r.atEnd()) return std::nullopt;
    return c;
}

}  // namespace tactiscope::devices::protocol
