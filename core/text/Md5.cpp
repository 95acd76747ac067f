// MD5 after RFC 1321: 64-byte blocks, four rounds of sixteen steps.
#include "core/text/Md5.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace tactiscope::core::text {
namespace {

constexpr std::array<int, 16> kShifts = {7, 12, 17, 22, 5, 9, 14, 20, 4, 11, 16, 23, 6, 10, 15, 21};

// The sines table: floor(2^32 · |sin(i + 1)|).
const std::array<std::uint32_t, 64>& sines()
{
    static const auto table = [] {
        std::array<std::uint32_t, 64> t{};
        for (std::size_t i = 0; i < t.size(); ++i)
            t[i] =
                static_cast<std::uint32_t>(std::floor(std::abs(std::sin(static_cast<double>(i + 1))) * 4294967296.0));
        return t;
    }();
    return table;
}

std::uint32_t littleEndian(const std::uint8_t* p)
{
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}

}  // namespace

Md5::Md5()
    : m_state{0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476}
{
}

void Md5::block(const std::uint8_t* data)
{
    std::array<std::uint32_t, 16> m;
    for (std::size_t i = 0; i < 16; ++i) m[i] = littleEndian(data + 4 * i);
    std::uint32_t a = m_state[0], b = m_state[1], c = m_state[2], d = m_state[3];
    for (std::size_t i = 0; i < 64; ++i) {
        std::uint32_t f;
        std::size_t g;
        switch (i / 16) {
        case 0:
            f = (b & c) | (~b & d), g = i;
            break;
        case 1:
            f = (d & b) | (~d & c), g = (5 * i + 1) % 16;
            break;
        case 2:
            f = b ^ c ^ d, g = (3 * i + 5) % 16;
            break;
        default:
            f = c ^ (b | ~d), g = (7 * i) % 16;
            break;
        }
        const std::uint32_t rotated = std::rotl(a + f + sines()[i] + m[g], kShifts[(i / 16) * 4 + i % 4]);
        a = d;
        d = c;
        c = b;
        b = b + rotated;
    }
    m_state[0] += a;
    m_state[1] += b;
    m_state[2] += c;
    m_state[3] += d;
}

void Md5::add(std::span<const std::uint8_t> bytes)
{
    m_length += bytes.size();
    std::size_t at = 0;
    if (m_buffered > 0) {
        const std::size_t n = std::min(bytes.size(), 64 - m_buffered);
        std::memcpy(m_buffer.data() + m_buffered, bytes.data(), n);
        m_buffered += n;
        at = n;
        if (m_buffered < 64) return;
        block(m_buffer.data());
        m_buffered = 0;
    }
    for (; at + 64 <= bytes.size(); at += 64) block(bytes.data() + at);
    m_buffered = bytes.size() - at;
    if (m_buffered > 0) std::memcpy(m_buffer.data(), bytes.data() + at, m_buffered);
}

void Md5::add(std::string_view text)
{
    add({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

std::string Md5::hex()
{
    const std::uint64_t bits = m_length * 8;
    std::array<std::uint8_t, 72> padding{0x80};
    const std::size_t padded = (m_buffered < 56 ? 56 : 120) - m_buffered;
    std::array<std::uint8_t, 8> length{};
    for (std::size_t i = 0; i < 8; ++i) length[i] = static_cast<std::uint8_t>(bits >> (8 * i));
    add(std::span(padding.data(), padded));
    add(length);
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string result;
    for (const std::uint32_t word : m_state)
        for (int i = 0; i < 4; ++i) {
            const auto byte = static_cast<std::uint8_t>(word >> (8 * i));
            result += kDigits[byte >> 4];
            result += kDigits[byte & 15];
        }
    return result;
}

std::string md5Hex(std::span<const std::uint8_t> bytes)
{
    Md5 md5;
    md5.add(bytes);
    return md5.hex();
}

}  // namespace tactiscope::core::text
