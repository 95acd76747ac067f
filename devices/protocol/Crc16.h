// CRC-16/CCITT-FALSE (polynomial 0x1021, initial value 0xFFFF, no
// reflection, no final XOR): check value 0x29B1 for "123456789". Chosen for
// the wire protocol because every microcontroller SDK has it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace tactiscope::devices::protocol {

std::uint16_t crc16Ccitt(std::span<const std::uint8_t> bytes, std::uint16_t crc = 0xFFFF);

}  // namespace tactiscope::devices::protocol
