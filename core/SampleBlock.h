// A SampleBlock is the unit that crosses threads: a few milliseconds of
// samples for every channel of one device, uniformly spaced in time.
//
// Values are stored channel-major (all samples of channel 0, then channel 1,
// ...) so a processor can take one channel as a contiguous span. Times are
// host seconds since the acquisition started: sample i of the block was
// taken at t0_s() + i * dt_s().
//
// firstSampleIndex() is the device's running count of samples per channel,
// so consecutive blocks of a lossless stream satisfy
// next.firstSampleIndex() == previous.endSampleIndex(); a larger value means
// samples were lost in between. sequence() is the device's frame sequence
// number, kept for diagnostics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tactiscope::core {

class SampleBlock {
public:
    SampleBlock() = default;

    // Zero-filled block. Throws std::invalid_argument when channelCount is 0,
    // dt_s is not a positive finite number, or t0_s is not finite.
    SampleBlock(std::size_t channelCount, std::size_t sampleCount, double t0_s, double dt_s,
                std::uint64_t firstSampleIndex = 0, std::uint32_t sequence = 0);

    std::size_t channelCount() const { return m_channelCount; }
    std::size_t sampleCount() const { return m_sampleCount; }
    bool empty() const { return m_sampleCount == 0; }

    double t0_s() const { return m_t0_s; }
    double dt_s() const { return m_dt_s; }
    double timeAt_s(std::size_t sample) const { return m_t0_s + static_cast<double>(sample) * m_dt_s; }
    // Time just past the last sample: where the next contiguous block starts.
    double endTime_s() const { return timeAt_s(m_sampleCount); }

    std::uint64_t firstSampleIndex() const { return m_firstSampleIndex; }
    std::uint64_t endSampleIndex() const { return m_firstSampleIndex + m_sampleCount; }
    std::uint32_t sequence() const { return m_sequence; }

    // Samples lost between a previous block that ended at `previousEndIndex`
    // and this one: 0 when contiguous, and 0 when this block restarts or
    // overlaps the count (a device reset is not a loss).
    std::uint64_t samplesLostAfter(std::uint64_t previousEndIndex) const
    {
        return m_firstSampleIndex > previousEndIndex ? m_firstSampleIndex - previousEndIndex : 0;
    }

    // Moves the block in time and sample numbering, e.g. to continue a
    // stream after a reconnection restarted the device's counters.
    void rebase(double timeOffset_s, std::uint64_t indexOffset)
    {
        m_t0_s += timeOffset_s;
        m_firstSampleIndex += indexOffset;
    }

    std::span<double> channel(std::size_t c);
    std::span<const double> channel(std::size_t c) const;
    double value(std::size_t c, std::size_t sample) const { return channel(c)[sample]; }

    std::span<const double> values() const { return m_values; }

private:
    std::size_t m_channelCount = 0;
    std::size_t m_sampleCount = 0;
    double m_t0_s = 0.0;
    double m_dt_s = 1.0;
    std::uint64_t m_firstSampleIndex = 0;
    std::uint32_t m_sequence = 0;
    std::vector<double> m_values;
};

}  // namespace tactiscope::core
