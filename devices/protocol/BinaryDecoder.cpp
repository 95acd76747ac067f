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

std::optional<std::size_t> BinaryDecoder::nextValidFrame(std::size_t from) const
{
    for (std::size_t i = from; i + kHeaderSize + kCrcSize <= m_buffer.size(); ++i) {
        const std::uint8_t* h = m_buffer.data() + i;
        if (h[0] != kSync0 || h[1] != kSync1 || h[2] != kVersion) continue;
        const std::size_t length = static_cast<std::size_t>(h[4] | (h[5] << 8));
        const std::size_t total = kHeaderSize + length + kCrcSize;
        if (length > kMaxPayload || i + total > m_buffer.size()) continue;
        const std::uint16_t expected = static_cast<std::uint16_t>(h[total - 2] | (h[total - 1] << 8));
        if (crc16Ccitt(std::span(h + 2, total - 4)) == expected) return i;
    }
    return std::nullopt;
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
        if (available < total) {
            // Incomplete: either a real frame still arriving, or a false sync
            // (A5 5A inside corrupted data) whose bogus length would hold up
            // the real frames behind it. Real frames never overlap, so a
            // complete, valid frame starting later proves this one false.
            if (const auto next = nextValidFrame(m_start + 1)) {
                skip(*next - m_start);
                continue;
            }
            break;
        }
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
