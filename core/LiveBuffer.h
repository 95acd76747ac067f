// LiveBuffer holds the most recent samples of every channel of one device for
// the live display. The acquisition thread appends whole blocks (it is a
// BlockSink); the GUI thread periodically takes everything new since its
// cursor. The mutex is held only while copying, never while drawing.
//
// A reader that falls more than capacity() samples behind loses the oldest
// ones; the loss is counted in its LiveCursor instead of going unnoticed.
#pragma once

#include "core/BlockSink.h"
#include "core/RingBuffer.h"

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace tactiscope::core {

// Where one reader is in the buffer, and what it has missed.
struct LiveCursor {
    std::uint64_t next = 0;     // absolute sample index to read next
    std::uint64_t overrun = 0;  // samples overwritten before this reader got them
};

// Samples handed to a reader: time and one vector per channel, equal lengths.
struct LiveChunk {
    std::uint64_t firstIndex = 0;
    std::vector<double> time_s;
    std::vector<std::vector<double>> values;

    std::size_t sampleCount() const { return time_s.size(); }
};

class LiveBuffer final : public BlockSink {
public:
    // capacitySamples: samples kept per channel. Throws std::invalid_argument
    // when either count is zero.
    LiveBuffer(std::size_t channelCount, std::size_t capacitySamples);

    std::size_t channelCount() const
    {
        const std::lock_guard lock(m_mutex);
        return m_channels.size();
    }
    std::size_t capacity() const { return m_time.capacity(); }

    // Writer side (acquisition thread). Throws std::invalid_argument when the
    // block's channel count differs from the buffer's.
    void consume(const SampleBlock& block) override;
    // New channels: NaN for the samples held before them.
    void channelsGrew(const std::vector<ChannelDescriptor>& all) override;

    // Reader side: copies at most maxSamples samples after cursor.next into
    // out (replacing its contents) and advances the cursor. When samples were
    // overwritten since the last read, they are skipped and added to
    // cursor.overrun. Returns the number of samples copied.
    std::size_t readNew(LiveCursor& cursor, LiveChunk& out, std::size_t maxSamples = SIZE_MAX) const;

    // Total samples per channel ever appended.
    std::uint64_t samplesWritten() const;

private:
    mutable std::mutex m_mutex;
    RingBuffer<double> m_time;
    std::vector<RingBuffer<double>> m_channels;
};

}  // namespace tactiscope::core
