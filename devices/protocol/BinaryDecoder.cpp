// TSP/1 frame synchronisation and checking.
#include "devices/protocol/BinaryDecoder.h"

#include "devices/protocol/Crc16.h"

#include <algorithm>

namespace tactiscope::devices::protocol {

void BinaryDecoder::reset()
{
    m_buffer.clear();
    m_start = 0;
    m_discarding = false;
    m_counters = {};
}

void BinaryDecoder::skip(std::size_t count)
{
    m_start += count;
    if (!m_discarding) {
        m_discarding = true;
        ++m_counters.resyncs;
    }
}

void BinaryDecoder::push(std::span<const std::uint8_t> bytes, std::vector<Frame>& out)
{
    m_counters.bytes += bytes.size();
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    while (m_buffer.size() - m_start >= 2) {
        // Find the sync pair.
        const auto from = m_buffer.begin() + static_cast<std::ptrdiff_t>(m_start);
        const auto sync = std::adjacent_find(from, m_buffer.end(),
                                             [](std::uint8_t a, std::uint8_t b) { return a == kSync0 && b == kSync1; });
        if (sync == m_buffer.end()) {
            // Keep a trailing 0xA5: it may be the first half of a sync.
            const std::size_t keep = m_buffer.back() == kSync0 ? 1 : 0;
            skip(m_buffer.size() - m_start - keep);
            break;
        }
        if (sync != from) skip(static_cast<std::size_t>(sync - from));

        const std::size_t available = m_buffer.size() - m_start;
        if (available < kHeaderSize) break;
        const std::uint8_t* h = m_buffer.data() + m_start;
        const std::size_t length = static_cast<std::size_t>(h[4] | (h[5] << 8));
        if (h[2] != kVersion || length > kMaxPayload) {
            skip(1);
            continue;
        }
        const std::size_t total = kHeaderSize + length + kCrcSize;
        if (available < total) break;
        const std::uint16_t expected = static_cast<std::uint16_t>(h[total - 2] | (h[total - 1] << 8));
        if (crc16Ccitt(std::span(h + 2, total - 4)) != expected) {
            ++m_counters.crcErrors;
            skip(1);
            continue;
        }
        Frame frame;
        frame.type = static_cast<FrameType>(h[3]);
        frame.sequence = static_cast<std::uint16_t>(h[6] | (h[7] << 8));
        frame.payload.assign(h + kHeaderSize, h + kHeaderSize + length);
        out.push_back(std::move(frame));
        ++m_counters.frames;
        m_start += total;
        m_discarding = false;
    }
    // Compact now and then so the buffer does not grow with the stream.
    if (m_start > 4096 || m_start == m_buffer.size()) {
        m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_start));
        m_start = 0;
    }
}

}  // namespace tactiscope::devices::protocol
