// TSP/1 bytes → SampleBlocks: decodes frames, applies the channel scaling of
// the last INFO frame, unwraps the device's 32-bit microsecond clock, counts
// samples lost to sequence gaps (gap × the previous frame's samples) and
// numbers samples so that the loss shows as a gap in firstSampleIndex.
//
// Without an INFO frame the channels are ch1…chN, unscaled, and the sample
// interval is taken from the timestamps of the first two DATA frames (the
// first frame waits for the second).
#pragma once

#include "core/SampleBlock.h"
#include "devices/protocol/BinaryDecoder.h"

#include <optional>
#include <span>
#include <vector>

namespace tactiscope::devices::protocol {

struct StreamOutput {
    std::vector<core::SampleBlock> blocks;
    std::vector<StatusPayload> statuses;
    bool infoChanged = false;
};

class BinaryStream {
public:
    void push(std::span<const std::uint8_t> bytes, StreamOutput& out);

    const std::optional<DeviceInfo>& info() const { return m_info; }
    // Known once an INFO or a second DATA frame has arrived.
    std::optional<double> sampleRate_hz() const;
    std::vector<core::ChannelDescriptor> channels() const;
    const DecoderCounters& counters() const { return m_counters; }
    void reset();

private:
    void onData(const Frame& frame, StreamOutput& out);
    void publish(const DataPayload& data, std::uint64_t timestamp_us, StreamOutput& out);
    std::uint64_t unwrap(std::uint32_t timestamp_us);

    BinaryDecoder m_decoder;
    DecoderCounters m_counters;
    std::optional<DeviceInfo> m_info;
    std::optional<double> m_estimatedInterval_s;
    std::optional<std::pair<DataPayload, std::uint64_t>> m_waiting;  // first frame, until the interval is known
    std::optional<std::uint16_t> m_lastSequence;
    std::uint16_t m_lastSamples = 0;
    std::optional<std::uint32_t> m_lastRawTimestamp;
    std::uint64_t m_wraps = 0;
    std::optional<std::uint64_t> m_firstTimestamp_us;
    std::uint64_t m_nextSampleIndex = 0;
    std::uint32_t m_blockSequence = 0;
    std::size_t m_dataChannels = 0;
    std::vector<Frame> m_frames;  // scratch
};

}  // namespace tactiscope::devices::protocol
