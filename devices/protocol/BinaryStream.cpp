// BinaryStream: frames to SampleBlocks with scaling, clock unwrap and gaps.
#include "devices/protocol/BinaryStream.h"

namespace tactiscope::devices::protocol {

void BinaryStream::reset()
{
    *this = BinaryStream{};
}

std::optional<double> BinaryStream::sampleRate_hz() const
{
    if (m_info && m_info->sampleRate_mhz > 0) return m_info->sampleRate_mhz / 1000.0;
    if (m_estimatedInterval_s) return 1.0 / *m_estimatedInterval_s;
    return std::nullopt;
}

std::vector<core::ChannelDescriptor> BinaryStream::channels() const
{
    std::vector<core::ChannelDescriptor> result;
    if (m_info) {
        for (const auto& c : m_info->channels) result.push_back(c.descriptor);
    } else {
        for (std::size_t c = 0; c < m_dataChannels; ++c)
            result.push_back({"ch" + std::to_string(c + 1), "", core::ChannelKind::Other});
    }
    return result;
}

std::uint64_t BinaryStream::unwrap(std::uint32_t raw)
{
    // A step back by more than half the range is the 32-bit counter wrapping.
    if (m_lastRawTimestamp && raw<*m_lastRawTimestamp&& * m_lastRawTimestamp - raw> 0x80000000u) ++m_wraps;
    m_lastRawTimestamp = raw;
    return (m_wraps << 32) + raw;
}

void BinaryStream::push(std::span<const std::uint8_t> bytes, StreamOutput& out)
{
    m_frames.clear();
    m_decoder.push(bytes, m_frames);
    for (const Frame& frame : m_frames) {
        switch (frame.type) {
        case FrameType::Info:
            if (auto info = parseInfo(frame.payload)) {
                m_info = std::move(info);
                out.infoChanged = true;
            } else {
                ++m_counters.malformedPayloads;
            }
            break;
        case FrameType::Data:
            onData(frame, out);
            break;
        case FrameType::Status:
            if (auto status = parseStatus(frame.payload))
                out.statuses.push_back(std::move(*status));
            else
                ++m_counters.malformedPayloads;
            break;
        case FrameType::Command:
            break;  // an echo or a loopback: not ours to act on
        default:
            ++m_counters.malformedPayloads;
        }
    }
    const auto& d = m_decoder.counters();
    m_counters.bytes = d.bytes;
    m_counters.frames = d.frames;
    m_counters.crcErrors = d.crcErrors;
    m_counters.resyncs = d.resyncs;
}

void BinaryStream::onData(const Frame& frame, StreamOutput& out)
{
    auto data = parseData(frame.payload);
    if (!data || (m_info && data->channelCount != m_info->channels.size())) {
        ++m_counters.malformedPayloads;
        return;
    }
    if (m_lastSequence) {
        const auto gap = static_cast<std::uint16_t>(frame.sequence - *m_lastSequence - 1);
        const std::uint64_t lost = static_cast<std::uint64_t>(gap) * m_lastSamples;
        m_counters.samplesLost += lost;
        m_nextSampleIndex += lost;
    }
    m_lastSequence = frame.sequence;
    m_lastSamples = data->samplesPerChannel;
    m_dataChannels = data->channelCount;
    const std::uint64_t timestamp = unwrap(data->timestamp_us);
    if (!m_firstTimestamp_us) m_firstTimestamp_us = timestamp;

    if (!sampleRate_hz()) {
        if (!m_waiting) {
            m_waiting.emplace(std::move(*data), timestamp);
            return;
        }
        const auto& [first, firstTime] = *m_waiting;
        if (timestamp > firstTime && first.samplesPerChannel > 0)
            m_estimatedInterval_s = static_cast<double>(timestamp - firstTime) * 1e-6 / first.samplesPerChannel;
        else
            m_estimatedInterval_s = 1e-3;  // nothing better to go on; corrected by INFO if it comes
    }
    if (m_waiting) {
        auto waiting = std::move(*m_waiting);
        m_waiting.reset();
        publish(waiting.first, waiting.second, out);
    }
    publish(*data, timestamp, out);
}

void BinaryStream::publish(const DataPayload& data, std::uint64_t timestamp_us, StreamOutput& out)
{
    const double dt = 1.0 / *sampleRate_hz();
    const double t0 = static_cast<double>(timestamp_us - *m_firstTimestamp_us) * 1e-6;
    core::SampleBlock block(data.channelCount, data.samplesPerChannel, t0, dt, m_nextSampleIndex, m_blockSequence++);
    for (std::size_t c = 0; c < data.channelCount; ++c) {
        const double scale = m_info ? static_cast<double>(m_info->channels[c].scale) : 1.0;
        const double offset = m_info ? static_cast<double>(m_info->channels[c].offset) : 0.0;
        auto channel = block.channel(c);
        for (std::size_t s = 0; s < data.samplesPerChannel; ++s)
            channel[s] = data.raw[s * data.channelCount + c] * scale + offset;
    }
    m_nextSampleIndex += data.samplesPerChannel;
    out.blocks.push_back(std::move(block));
}

}  // namespace tactiscope::devices::protocol
