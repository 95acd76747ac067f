// LiveBuffer: the lock-guarded ring shared by the acquisition and GUI threads.
#include "core/LiveBuffer.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tactiscope::core {

LiveBuffer::LiveBuffer(std::size_t channelCount, std::size_t capacitySamples)
    : m_time(capacitySamples)
{
    if (channelCount == 0) throw std::invalid_argument("LiveBuffer needs at least one channel");
    m_channels.reserve(channelCount);
    for (std::size_t c = 0; c < channelCount; ++c) m_channels.emplace_back(capacitySamples);
}

void LiveBuffer::consume(const SampleBlock& block)
{
    if (block.channelCount() != m_channels.size())
        throw std::invalid_argument("LiveBuffer: block channel count does not match the buffer");
    const std::lock_guard lock(m_mutex);
    for (std::size_t i = 0; i < block.sampleCount(); ++i) m_time.push(block.timeAt_s(i));
    for (std::size_t c = 0; c < m_channels.size(); ++c) m_channels[c].push(block.channel(c));
}

// A channel that began mid-stream holds no value before it: NaN, as a hole.
void LiveBuffer::channelsGrew(const std::vector<ChannelDescriptor>& all)
{
    const std::lock_guard lock(m_mutex);
    while (m_channels.size() < all.size()) {
        m_channels.emplace_back(m_time.capacity());
        m_channels.back().fillTo(m_time.endIndex(), std::numeric_limits<double>::quiet_NaN());
    }
}

std::size_t LiveBuffer::readNew(LiveCursor& cursor, LiveChunk& out, std::size_t maxSamples) const
{
    const std::lock_guard lock(m_mutex);
    if (cursor.next < m_time.oldestIndex()) {
        cursor.overrun += m_time.oldestIndex() - cursor.next;
        cursor.next = m_time.oldestIndex();
    }
    const auto available = static_cast<std::size_t>(m_time.endIndex() - cursor.next);
    const std::size_t count = std::min(available, maxSamples);

    out.firstIndex = cursor.next;
    out.time_s.resize(count);
    m_time.copy(cursor.next, out.time_s);
    out.values.resize(m_channels.size());
    for (std::size_t c = 0; c < m_channels.size(); ++c) {
        out.values[c].resize(count);
        m_channels[c].copy(cursor.next, out.values[c]);
    }
    cursor.next += count;
    return count;
}

std::uint64_t LiveBuffer::samplesWritten() const
{
    const std::lock_guard lock(m_mutex);
    return m_time.endIndex();
}

}  // namespace tactiscope::core
