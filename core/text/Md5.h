// MD5 (RFC 1321) of bytes, as lowercase hex: the digest PostgreSQL's md5()
// gives, so a station and the central store can compare what they hold
// without sending it back. A check against damage in transit, not a
// defence against forgery (the server's roles are that).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace tactiscope::core::text {

class Md5 {
public:
    Md5();
    void add(std::span<const std::uint8_t> bytes);
    void add(std::string_view text);
    std::string hex();  // ends the digest

private:
    void block(const std::uint8_t* data);

    std::array<std::uint32_t, 4> m_state;
    std::array<std::uint8_t, 64> m_buffer{};
    std::size_t m_buffered = 0;
    std::uint64_t m_length = 0;  // bytes
};

std::string md5Hex(std::span<const std::uint8_t> bytes);

}  // namespace tactiscope::core::text
