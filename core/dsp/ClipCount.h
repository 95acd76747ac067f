// Samples of a channel held at its extreme: an ADC that clips returns its
// full scale, sample after sample. Where the channel's range is known
// (a board's counts) a sample at or beyond it is clipped; otherwise a run
// of three or more equal samples at the recording's highest or lowest
// value is (a flat top that no live signal with noise draws). A channel
// that never varies is flat, not clipped; nor is one whose samples repeat
// elsewhere too (more than 1 % of them: exact steps, a coarse converter),
// where a run at the top says nothing of clipping.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace tactiscope::core::dsp {

struct ChannelRange {
    double low = 0.0;
    double high = 0.0;
};

class ClipCounter {
public:
    explicit ClipCounter(std::optional<ChannelRange> range = std::nullopt)
        : m_range(range)
    {
    }
    void push(double value);
    std::uint64_t clipped() const;

private:
    void endRun();

    std::optional<ChannelRange> m_range;
    std::uint64_t m_beyondRange = 0;
    double m_top = -std::numeric_limits<double>::infinity();
    double m_bottom = std::numeric_limits<double>::infinity();
    std::uint64_t m_atTop = 0;
    std::uint64_t m_atBottom = 0;
    double m_runValue = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t m_runLength = 0;
    std::uint64_t m_samples = 0;
    std::uint64_t m_repeats = 0;  // samples equal to the one before
};

}  // namespace tactiscope::core::dsp
