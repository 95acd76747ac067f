// Bytes → TSP/1 frames. Takes chunks cut anywhere (a frame split across
// reads, several frames in one read, garbage before, between or inside
// frames). After a bad CRC, a wrong version or an impossible length it
// resumes the search one byte after the rejected sync, so a good frame that
// follows garbage is never lost; and a false sync inside garbage cannot hold
// up the frames after it, because a complete valid frame further on proves
// it false. Knows nothing of ports or widgets.
#pragma once

#include "devices/protocol/BinaryProtocol.h"
#include "devices/protocol/DecoderCounters.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::devices::protocol {

class BinaryDecoder {
public:
    // Appends every complete, checked frame in `bytes` (with what is
    // buffered from earlier calls) to `out`.
    void push(std::span<const std::uint8_t> bytes, std::vector<Frame>& out);
    const DecoderCounters& counters() const { return m_counters; }
    void reset();

private:
    void skip(std::size_t count);
    // Offset of the first complete frame with a good CRC at or after `from`.
    std::optional<std::size_t> nextValidFrame(std::size_t from) const;

    std::vector<std::uint8_t> m_buffer;
    std::size_t m_start = 0;  // first unconsumed byte in m_buffer
    bool m_discarding = false;
    DecoderCounters m_counters;
};

}  // namespace tactiscope::devices::protocol
