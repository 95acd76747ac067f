// TextStream: line samples into uniformly spaced blocks.
#include "devices/protocol/TextStream.h"

#include "core/UnitScale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tactiscope::devices::protocol {

TextStream::TextStream(std::optional<double> sampleRate_hz, std::map<std::string, std::string> units)
    : m_givenUnits(std::move(units)),
      m_rate_hz(sampleRate_hz),
      m_checkingGivenRate(sampleRate_hz.has_value())
{
    if (sampleRate_hz && !(*sampleRate_hz > 0.0)) throw std::invalid_argument("text stream rate must be positive");
}

// A label may say the channel's role (docs/protocol.md, "Channel roles"):
// "a@cantilever-a" is channel a as cantilever A, and a label that is a
// role's name ("stiff-beam") plays that role. Anything else is only a name.
std::vector<core::ChannelDescriptor> TextStream::channels() const
{
    return described(nullptr);
}

std::vector<core::ChannelDescriptor> TextStream::described(std::vector<double>* toStored) const
{
    std::vector<core::ChannelDescriptor> result;
    const auto& names = m_decoder.channelNames();
    for (std::size_t c = 0; c < names.size(); ++c) {
        const std::string& label = names[c];
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
        const auto given = m_givenUnits.find(channel.name);
        const double factor =
            core::giveUnit(channel, given != m_givenUnits.end() ? given->second : m_decoder.channelUnits()[c]);
        if (toStored) toStored->push_back(factor);
        result.push_back(std::move(channel));
    }
    return result;
}

std::vector<std::string> TextStream::unknownUnitNames() const
{
    const auto known = channels();
    std::vector<std::string> unknown;
    for (const auto& [name, unit] : m_givenUnits)
        if (std::ranges::find(known, name, &core::ChannelDescriptor::name) == known.end()) unknown.push_back(name);
    return unknown;
}

void TextStream::push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<core::SampleBlock>& out,
                      std::vector<double>* arrivals)
{
    m_scratch.clear();
    m_decoder.push(bytes, hostTime_s, m_scratch);
    if (m_checkingGivenRate) {
        for (const auto& sample : m_scratch) m_lineRate.add(sample.hostTime_s, sample.boardTime);
        checkGivenRate();
    }
    if (!m_rate_hz) {
        for (auto& sample : m_scratch) {
            m_lineRate.add(sample.hostTime_s, sample.boardTime);
            m_held.push_back(std::move(sample));
        }
        if (!m_lineRate.settled()) return;
        m_measured = m_lineRate.estimate();
        m_rate_hz = m_measured->rate_hz;
        m_lineRate = {};
        publish(m_held, out, arrivals);
        m_held.clear();
        return;
    }
    publish(m_scratch, out, arrivals);
}

// A rate given by the user against the arrivals, once they settle: a
// mismatch is said, since every time in the recording rests on the rate.
void TextStream::checkGivenRate()
{
    if (!m_lineRate.settled()) return;
    m_checkingGivenRate = false;
    const auto measured = m_lineRate.estimate();
    m_lineRate = {};
    // Off by more than the measurement can tell, and than a tenth of a
    // percent (0.4 s in a 6-minute recording).
    const double tolerance_hz = std::max(kGivenRateTolerance * measured->rate_hz, 3.0 * measured->u_hz.value_or(0.0));
    if (std::abs(*m_rate_hz - measured->rate_hz) <= tolerance_hz) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "the lines arrive at %.6g Hz (%s, over %.1f s), not at the %.6g Hz given: every time in this "
                  "recording is off by %.2f %%; give --rate as measured, or none to have the lines timed",
                  measured->rate_hz, measured->boardClock ? "by the board's clock" : "by the host's clock",
                  measured->span_s, *m_rate_hz, 100.0 * (measured->rate_hz / *m_rate_hz - 1.0));
    m_rateWarning = text;
}

DecoderCounters TextStream::counters() const
{
    DecoderCounters counters = m_decoder.counters();
    counters.samplesLost = m_samplesLost;
    return counters;
}

// The sample number of a readable line: the next one, or, by the board's
// clock, as many periods on from its last stamp as its stamp says (the
// lines between were lost).
std::uint64_t TextStream::indexOf(const TextSample& sample) const
{
    const auto stamp_s = boardSeconds(sample);
    if (!stamp_s || !m_lastBoardTime || !(*stamp_s > m_lastBoardTime->first)) return m_nextSampleIndex;
    const double periods = std::max(1.0, std::round((*stamp_s - m_lastBoardTime->first) * *m_rate_hz));
    return std::max(m_nextSampleIndex, m_lastBoardTime->second + static_cast<std::uint64_t>(periods));
}

std::optional<double> TextStream::boardSeconds(const TextSample& sample) const
{
    if (!sample.boardTime || !m_measured || !m_measured->boardClock) return std::nullopt;
    return sample.boardTime->value * m_measured->boardSecondsPerUnit;
}

void TextStream::accept(const TextSample& sample, std::uint64_t index)
{
    m_samplesLost += index - m_nextSampleIndex;
    m_nextSampleIndex = index + 1;
    if (const auto stamp_s = boardSeconds(sample)) m_lastBoardTime = {*stamp_s, index};
}

// One block per run of lines that arrived together and follow each other;
// each unreadable line, and each sample the board's clock says was lost,
// moves the index on.
void TextStream::publish(std::vector<TextSample>& samples, std::vector<core::SampleBlock>& out,
                         std::vector<double>* arrivals)
{
    const double dt = 1.0 / *m_rate_hz;
    if (m_toStored.size() < m_decoder.channelNames().size()) {
        m_toStored.clear();
        described(&m_toStored);
    }
    std::size_t s = 0;
    while (s < samples.size()) {
        if (samples[s].values.empty()) {
            ++m_samplesLost;
            ++m_nextSampleIndex;
            ++s;
            continue;
        }
        const std::uint64_t first = indexOf(samples[s]);
        accept(samples[s], first);
        if (samples[s].layoutChange) m_layoutChanges.push_back({first, std::move(*samples[s].layoutChange)});
        const std::size_t channels = samples[s].values.size();
        std::size_t end = s + 1;
        while (end < samples.size() && samples[end].values.size() == channels && !samples[end].layoutChange &&
               samples[end].hostTime_s == samples[s].hostTime_s && indexOf(samples[end]) == m_nextSampleIndex) {
            accept(samples[end], m_nextSampleIndex);
            ++end;
        }
        core::SampleBlock block(channels, end - s, static_cast<double>(first) * dt, dt, first, m_blockSequence++);
        for (std::size_t i = s; i < end; ++i)
            for (std::size_t c = 0; c < channels; ++c) block.channel(c)[i - s] = samples[i].values[c] * m_toStored[c];
        out.push_back(std::move(block));
        if (arrivals) arrivals->push_back(samples[end - 1].hostTime_s);
        s = end;
    }
}

}  // namespace tactiscope::devices::protocol
