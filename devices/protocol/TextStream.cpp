// TextStream: line samples into uniformly spaced blocks.
#include "devices/protocol/TextStream.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::devices::protocol {

TextStream::TextStream(std::optional<double> sampleRate_hz)
    : m_rate_hz(sampleRate_hz)
{
    if (sampleRate_hz && !(*sampleRate_hz > 0.0)) throw std::invalid_argument("text stream rate must be positive");
}

// A label may say the channel's role (docs/protocol.md, "Channel roles"):
// "a@cantilever-a" is channel a as cantilever A, and a label that is a
// role's name ("stiff-beam") plays that role. Anything else is only a name.
std::vector<core::ChannelDescriptor> TextStream::channels() const
{
    std::vector<core::ChannelDescriptor> result;
    for (const auto& label : m_decoder.channelNames()) {
        core::ChannelDescriptor channel{label, "", core::ChannelKind::Other};
        const auto at = label.rfind('@');
        if (const auto role = core::channelRoleFromString(label)) {
            channel.role = role;
        } else if (at != std::string::npos && at > 0) {
            if (const auto named = core::channelRoleFromString(std::string_view(label).substr(at + 1))) {
                channel.name = label.substr(0, at);
                channel.role = named;
            }
        }
        result.push_back(std::move(channel));
    }
    return result;
}

void TextStream::push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<core::SampleBlock>& out)
{
    m_scratch.clear();
    m_decoder.push(bytes, hostTime_s, m_scratch);
    if (!m_rate_hz) {
        m_held.insert(m_held.end(), m_scratch.begin(), m_scratch.end());
        if (m_held.empty()) return;
        const double first_s = m_held.front().hostTime_s;
        const double last_s = m_held.back().hostTime_s;
        if (last_s - first_s < kEstimationWindow_s) return;
        // Lines arrive in bursts (USB packets); what counts is how many
        // arrive over a long stretch, once the backlog that waited in the
        // port (read in the first moments, however many reads it takes) is
        // through: the lines after kSettle_s, over the time after it.
        const double settled_s = first_s + kSettle_s;
        const auto later = std::count_if(m_held.begin(), m_held.end(),
                                         [settled_s](const TextSample& s) { return s.hostTime_s > settled_s; });
        if (later < 2) return;
        m_rate_hz = static_cast<double>(later) / (last_s - settled_s);
        publish(m_held, out);
        m_held.clear();
        return;
    }
    publish(m_scratch, out);
}

DecoderCounters TextStream::counters() const
{
    DecoderCounters counters = m_decoder.counters();
    counters.samplesLost = m_samplesLost;
    return counters;
}

// One block per run of readable lines; each unreadable line between runs
// moves the index on by one.
void TextStream::publish(std::vector<TextSample>& samples, std::vector<core::SampleBlock>& out)
{
    const double dt = 1.0 / *m_rate_hz;
    std::size_t s = 0;
    while (s < samples.size()) {
        if (samples[s].values.empty()) {
            ++m_samplesLost;
            ++m_nextSampleIndex;
            ++s;
            continue;
        }
        std::size_t end = s;
        while (end < samples.size() && !samples[end].values.empty()) ++end;
        const std::size_t channels = samples[s].values.size();
        core::SampleBlock block(channels, end - s, static_cast<double>(m_nextSampleIndex) * dt, dt, m_nextSampleIndex,
                                m_blockSequence++);
        for (std::size_t i = s; i < end; ++i)
            for (std::size_t c = 0; c < channels; ++c) block.channel(c)[i - s] = samples[i].values[c];
        m_nextSampleIndex += end - s;
        out.push_back(std::move(block));
        s = end;
    }
}

}  // namespace tactiscope::devices::protocol
