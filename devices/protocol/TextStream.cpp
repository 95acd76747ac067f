// TextStream: line samples into uniformly spaced blocks.
#include "devices/protocol/TextStream.h"

#include <stdexcept>

namespace tactiscope::devices::protocol {

TextStream::TextStream(std::optional<double> sampleRate_hz)
    : m_rate_hz(sampleRate_hz)
{
    if (sampleRate_hz && !(*sampleRate_hz > 0.0)) throw std::invalid_argument("text stream rate must be positive");
}

std::vector<core::ChannelDescriptor> TextStream::channels() const
{
    std::vector<core::ChannelDescriptor> result;
    for (const auto& name : m_decoder.channelNames()) result.push_back({name, "", core::ChannelKind::Other});
    return result;
}

void TextStream::push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<core::SampleBlock>& out)
{
    m_scratch.clear();
    m_decoder.push(bytes, hostTime_s, m_scratch);
    if (!m_rate_hz) {
        m_held.insert(m_held.end(), m_scratch.begin(), m_scratch.end());
        if (m_held.size() < 3 || m_held.back().hostTime_s - m_held.front().hostTime_s < kEstimationWindow_s) return;
        // Lines arrive in bursts (USB packets); over 2 s the count is what matters.
        m_rate_hz = static_cast<double>(m_held.size() - 1) / (m_held.back().hostTime_s - m_held.front().hostTime_s);
        publish(m_held, out);
        m_held.clear();
        return;
    }
    publish(m_scratch, out);
}

void TextStream::publish(std::vector<TextSample>& samples, std::vector<core::SampleBlock>& out)
{
    if (samples.empty()) return;
    const std::size_t channels = samples.front().values.size();
    const double dt = 1.0 / *m_rate_hz;
    core::SampleBlock block(channels, samples.size(), static_cast<double>(m_nextSampleIndex) * dt, dt,
                            m_nextSampleIndex, m_blockSequence++);
    for (std::size_t s = 0; s < samples.size(); ++s) {
        for (std::size_t c = 0; c < channels; ++c) block.channel(c)[s] = samples[s].values[c];
    }
    m_nextSampleIndex += samples.size();
    out.push_back(std::move(block));
}

}  // namespace tactiscope::devices::protocol
