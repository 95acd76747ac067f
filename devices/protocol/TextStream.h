// Serial-Plotter text → SampleBlocks. Text carries no timing: the sample
// rate is the one given, or (none given) estimated from the arrival times of
// the lines of the first 2 s, which are held back until then. The lines of
// the first half second are not counted in the estimate (a backlog that
// waited in the port arrives then, at once); the lines after it over the
// time they took are.
// Each block holds the lines of one read; a line that could not be read is
// a lost sample (a gap of one), so the lines after it keep their time.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/SampleBlock.h"
#include "devices/protocol/TextDecoder.h"

#include <optional>
#include <span>
#include <vector>

namespace tactiscope::devices::protocol {

class TextStream {
public:
    // A given rate must be positive. Throws std::invalid_argument otherwise.
    explicit TextStream(std::optional<double> sampleRate_hz = std::nullopt);

    // hostTime_s: when the bytes arrived (seconds on a steady clock).
    void push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<core::SampleBlock>& out);

    std::optional<double> sampleRate_hz() const { return m_rate_hz; }
    std::vector<core::ChannelDescriptor> channels() const;
    DecoderCounters counters() const;

    static constexpr double kEstimationWindow_s = 2.0;
    static constexpr double kSettle_s = 0.5;

private:
    void publish(std::vector<TextSample>& samples, std::vector<core::SampleBlock>& out);

    TextDecoder m_decoder;
    std::optional<double> m_rate_hz;
    std::vector<TextSample> m_held;  // until the rate is known
    std::vector<TextSample> m_scratch;
    std::uint64_t m_nextSampleIndex = 0;
    std::uint64_t m_samplesLost = 0;
    std::uint32_t m_blockSequence = 0;
};

}  // namespace tactiscope::devices::protocol
