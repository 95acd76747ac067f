// The signal chain: rounding to the stored precision, the filters with
// their restarts, the math channels, and the re-analysis that runs the
// same chain over stored samples.
#include "core/signal/SignalChain.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::signal {
namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// A sample as the store keeps it (binary32), so the live chain and a
// re-analysis of the stored samples read the same numbers.
double asStored(double value)
{
    return static_cast<double>(static_cast<float>(value));
}

std::vector<std::string> namesOf(const std::vector<ChannelDescriptor>& channels)
{
    std::vector<std::string> names;
    for (const auto& channel : channels) names.push_back(channel.name);
    return names;
}

}  // namespace

std::string filteredName(const std::string& channel)
{
    return channel + ".filtered";
}

SignalChain::SignalChain(const SignalSetup& setup, const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                         std::size_t outputCapacity, double replay_s, std::size_t displayCapacity)
    : m_setup(setup),
      m_channelCount(channels.size())
{
    if (auto refusal = signalSetupRefusal(setup, namesOf(channels), sampleRate_hz))
        throw std::invalid_argument(*refusal);
    if (setup.empty()) throw std::invalid_argument("a signal chain needs a filter or a math channel");
    for (const auto& filter : setup.filters) {
        const auto channel = static_cast<std::size_t>(
            std::ranges::find(channels, filter.channel, &ChannelDescriptor::name) - channels.begin());
        m_filtered.push_back(channel);
        m_filters.emplace_back(filter.settings, sampleRate_hz);
        ChannelDescriptor output = channels[channel];
        output.name = filteredName(filter.channel);
        output.role = std::nullopt;
        m_outputs.push_back(std::move(output));
    }
    if (!setup.math.empty()) {
        m_math = std::make_unique<math::MathChannels>(math::mathInputs(channels), setup.math);
        for (const auto& definition : setup.math)
            m_outputs.push_back({definition.name, definition.unit == "1" ? "" : definition.unit, ChannelKind::Other});
    }
    m_output = std::make_shared<LiveBuffer>(m_outputs.size(), std::max<std::size_t>(outputCapacity, 1));
    if (displayCapacity > 0) {
        m_display = std::make_shared<LiveBuffer>(m_channelCount, displayCapacity);
        if (!setup.math.empty()) m_mathOutput = std::make_shared<LiveBuffer>(setup.math.size(), displayCapacity);
    }
    // A stored state of the wrong size is refused here, not on the acquisition thread.
    m_startState = setup.startState;
    for (std::size_t f = 0; f < m_startState.size(); ++f) {
        m_filters[f].startFrom(m_startState[f]);
        m_filters[f].reset();
    }
    const auto keptCapacity = static_cast<std::size_t>(std::ceil(std::max(replay_s, 0.0) * sampleRate_hz));
    if (keptCapacity > 0) m_kept.assign(m_filters.size(), RingBuffer<float>(keptCapacity));
}

SignalChain::~SignalChain() = default;

std::vector<ChannelDescriptor> SignalChain::mathOutputs() const
{
    return {m_outputs.begin() + static_cast<std::ptrdiff_t>(m_filters.size()), m_outputs.end()};
}

double SignalChain::delay_s(std::size_t index) const
{
    return index < m_filters.size() ? m_filters[index].delay_s() : 0.0;
}

void SignalChain::recordingBegins(std::uint64_t first, std::function<void(StartState)> found)
{
    const std::lock_guard lock(m_beginMutex);
    m_begin = Begin{first, std::move(found)};
}

SignalChain::StartState SignalChain::states() const
{
    StartState states;
    for (const auto& filter : m_filters) states.push_back(filter.sectionsState());
    return states;
}

// Samples the device lost: missing for the filters, which start again after them.
void SignalChain::lose(std::uint64_t samples)
{
    for (auto& filter : m_filters) filter.reset();
    if (m_kept.empty()) return;
    const auto held = std::min<std::uint64_t>(samples, m_kept.front().capacity());
    if (held < samples) {  // only the newest are kept: the rings start again after the rest
        m_keptBase += m_kept.front().endIndex() + samples - held;
        for (auto& kept : m_kept) kept.clear();
    }
    for (auto& kept : m_kept)
        for (std::uint64_t i = 0; i < held; ++i) kept.push(std::numeric_limits<float>::quiet_NaN());
}

// A beginning in this block is placed at `offset`; one before it is found
// again from what was kept (beginPassed()) and taken no further.
std::optional<SignalChain::Begin> SignalChain::takeBegin(const SampleBlock& block, std::size_t& offset)
{
    std::optional<Begin> begin;
    {
        const std::lock_guard lock(m_beginMutex);
        if (!m_begin || m_begin->first >= block.endSampleIndex()) return std::nullopt;
        begin = std::exchange(m_begin, std::nullopt);
    }
    if (begin->first >= block.firstSampleIndex()) {
        offset = static_cast<std::size_t>(begin->first - block.firstSampleIndex());
        return begin;
    }
    beginPassed(*begin);
    return std::nullopt;
}

// A beginning the chain has passed: each filter's state there is found by
// running it from the last snapshot before over what was kept; the filter
// then goes on from that state with its moving average afresh, over what
// came since, as it would have had it heard in time.
void SignalChain::beginPassed(const Begin& begin)
{
    StartState found;
    for (std::size_t f = 0; f < m_filters.size(); ++f) {
        if (m_kept.empty() || m_snapshots.empty()) {  // nothing kept: where it stands now
            found.push_back(m_filters[f].sectionsState());
            m_filters[f].startFrom(found.back());
            continue;
        }
        const auto& kept = m_kept[f];
        auto snapshot = std::ranges::find_if(m_snapshots.rbegin(), m_snapshots.rend(),
                                             [&](const Snapshot& s) { return s.first <= begin.first; });
        const Snapshot& from = snapshot == m_snapshots.rend() ? m_snapshots.front() : *snapshot;
        const std::uint64_t at = std::max(begin.first, from.first);
        dsp::ChannelFilter scratch = m_filters[f];
        scratch.startFrom(from.states[f]);
        for (std::uint64_t i = from.first; i < at; ++i) scratch.process(static_cast<double>(kept.at(i - m_keptBase)));
        found.push_back(scratch.sectionsState());
        m_filters[f].startFrom(found.back());
        for (std::uint64_t r = at - m_keptBase; r < kept.endIndex(); ++r)
            m_filters[f].process(static_cast<double>(kept.at(r)));
    }
    begin.found(std::move(found));
}

void SignalChain::consume(const SampleBlock& block)
{
    if (block.empty()) return;
    if (!m_next || block.firstSampleIndex() < *m_next) {
        // The first block (from where a recording's filters stood, in
        // re-analysis), or a device that restarted its count: nothing
        // before it is this stream's.
        for (std::size_t f = 0; f < m_filters.size(); ++f)
            m_filters[f].startFrom(!m_next && f < m_startState.size() ? m_startState[f] : std::nullopt);
        for (auto& kept : m_kept) kept.clear();
        m_snapshots.clear();
        m_keptBase = block.firstSampleIndex();
    } else if (const auto lost = block.samplesLostAfter(*m_next)) {
        lose(lost);
    }
    m_next = block.endSampleIndex();
    m_lastFirst = block.firstSampleIndex();

    const std::size_t n = block.sampleCount();
    m_values.resize(m_channelCount);
    for (std::size_t c = 0; c < m_channelCount; ++c) {
        m_values[c].resize(n);
        const auto in = c < block.channelCount() ? block.channel(c) : std::span<const double>();
        for (std::size_t i = 0; i < n; ++i) m_values[c][i] = i < in.size() ? asStored(in[i]) : kMissing;
    }
    if (!m_kept.empty()) {  // where the filters stand at this block, while it is kept
        m_snapshots.push_back({block.firstSampleIndex(), states()});
        const std::uint64_t oldest = m_keptBase + m_kept.front().oldestIndex();
        while (m_snapshots.front().first < oldest) m_snapshots.pop_front();  // its samples are gone
    }
    std::size_t beginAt = n;
    const auto begin = takeBegin(block, beginAt);
    StartState found(m_filters.size());
    for (std::size_t f = 0; f < m_filters.size(); ++f) {
        auto& values = m_values[m_filtered[f]];
        if (!m_kept.empty())
            for (const double v : values) m_kept[f].push(static_cast<float>(v));
        for (std::size_t i = 0; i < n; ++i) {
            if (begin && i == beginAt) {
                found[f] = m_filters[f].sectionsState();
                m_filters[f].startFrom(found[f]);
            }
            values[i] = m_filters[f].process(values[i]);
        }
    }
    if (begin) begin->found(std::move(found));

    SampleBlock out(m_outputs.size(), n, block.t0_s(), block.dt_s(), block.firstSampleIndex(), block.sequence());
    for (std::size_t f = 0; f < m_filters.size(); ++f)
        std::ranges::copy(m_values[m_filtered[f]], out.channel(f).begin());
    if (m_math) {
        std::vector<std::span<const double>> inputs(m_values.begin(), m_values.end());
        m_math->evaluate(inputs, m_mathValues);
        for (std::size_t d = 0; d < m_mathValues.size(); ++d)
            std::ranges::copy(m_mathValues[d], out.channel(m_filters.size() + d).begin());
    }
    m_output->consume(out);
    if (m_display) {
        SampleBlock shown(m_channelCount, n, block.t0_s(), block.dt_s(), block.firstSampleIndex(), block.sequence());
        for (std::size_t c = 0; c < m_channelCount; ++c) std::ranges::copy(m_values[c], shown.channel(c).begin());
        m_display->consume(shown);
    }
    if (m_mathOutput) {
        SampleBlock math(m_mathValues.size(), n, block.t0_s(), block.dt_s(), block.firstSampleIndex(),
                         block.sequence());
        for (std::size_t d = 0; d < m_mathValues.size(); ++d)
            std::ranges::copy(m_mathValues[d], math.channel(d).begin());
        m_mathOutput->consume(math);
    }
}

void SignalChain::filteredCopy(const SampleBlock& block, SampleBlock& out) const
{
    out = block;
    const bool last = !m_filters.empty() && block.firstSampleIndex() == m_lastFirst && !m_values.empty() &&
                      m_values.front().size() == block.sampleCount();
    if (!last) return;
    for (const std::size_t channel : m_filtered)
        if (channel < out.channelCount()) std::ranges::copy(m_values[channel], out.channel(channel).begin());
}

std::vector<std::vector<double>> chainSeries(const SignalSetup& setup, const std::vector<ChannelDescriptor>& channels,
                                             double sampleRate_hz, const std::vector<std::vector<double>>& values)
{
    const std::size_t n = values.empty() ? 0 : values.front().size();
    SignalChain chain(setup, channels, sampleRate_hz, n + 1);
    std::vector<std::vector<double>> series(chain.outputs().size());
    if (n == 0) return series;
    SampleBlock block(channels.size(), n, 0.0, 1.0 / sampleRate_hz);
    for (std::size_t c = 0; c < channels.size() && c < values.size(); ++c)
        std::ranges::copy(values[c], block.channel(c).begin());
    chain.consume(block);
    LiveCursor cursor;
    LiveChunk chunk;
    chain.output()->readNew(cursor, chunk);
    for (std::size_t o = 0; o < series.size(); ++o) series[o] = std::move(chunk.values[o]);
    return series;
}

}  // namespace tactiscope::core::signal
