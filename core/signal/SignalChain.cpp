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

void SignalChain::restartAt(std::uint64_t first)
{
    const std::lock_guard lock(m_restartMutex);
    m_restart = first;
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

// A restart at a sample already passed re-runs the filters from it over
// what was kept; one within this block is placed at `restartOffset`.
void SignalChain::applyRestart(const SampleBlock& block, std::size_t& restartOffset)
{
    std::optional<std::uint64_t> restart;
    {
        const std::lock_guard lock(m_restartMutex);
        if (!m_restart || *m_restart >= block.endSampleIndex()) return;
        restart = std::exchange(m_restart, std::nullopt);
    }
    if (*restart >= block.firstSampleIndex()) {
        restartOffset = static_cast<std::size_t>(*restart - block.firstSampleIndex());
        return;
    }
    for (std::size_t f = 0; f < m_filters.size(); ++f) {
        m_filters[f].reset();
        if (m_kept.empty()) continue;
        const auto& kept = m_kept[f];
        const std::uint64_t from = std::max(*restart > m_keptBase ? *restart - m_keptBase : 0, kept.oldestIndex());
        for (std::uint64_t r = from; r < kept.endIndex(); ++r) m_filters[f].process(static_cast<double>(kept.at(r)));
    }
}

void SignalChain::consume(const SampleBlock& block)
{
    if (block.empty()) return;
    if (!m_next || block.firstSampleIndex() < *m_next) {
        // The first block, or a device that restarted its count: nothing
        // before it is this stream's.
        for (auto& filter : m_filters) filter.reset();
        for (auto& kept : m_kept) kept.clear();
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
    std::size_t restartOffset = n;
    applyRestart(block, restartOffset);
    for (std::size_t f = 0; f < m_filters.size(); ++f) {
        auto& values = m_values[m_filtered[f]];
        if (!m_kept.empty())
            for (const double v : values) m_kept[f].push(static_cast<float>(v));
        for (std::size_t i = 0; i < n; ++i) {
            if (i == restartOffset) m_filters[f].reset();
            values[i] = m_filters[f].process(values[i]);
        }
    }

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
