// The recorded signal setup's columns for an export, a window at a time.
#include "core/signal/SignalColumns.h"

#include "core/SampleBlock.h"
#include "core/derived/DerivedLane.h"
#include "core/derived/ExactOverview.h"

#include <algorithm>

namespace tactiscope::core::signal {
namespace {

// Samples the chain takes at a time, and its output holds: a window of
// an export is read in as many pieces.
constexpr std::size_t kPiece = 1 << 16;

std::vector<ChannelDescriptor> storedChannels(storage::SessionSource& store, std::int64_t session)
{
    std::vector<ChannelDescriptor> channels;
    for (const auto& stored : store.channels(session)) channels.push_back(stored.descriptor);
    return channels;
}

}  // namespace

SignalColumns::SignalColumns(storage::SessionSource& store, std::int64_t session, SignalSetup setup,
                             std::unique_ptr<storage::ComputedColumns>&& derived)
    : m_store(store),
      m_session(session),
      m_setup(std::move(setup)),
      m_channels(storedChannels(store, session)),
      m_rate_hz(store.channels(session).empty() ? 0.0 : store.channels(session).front().sampleRate_hz),
      m_chain(std::make_unique<SignalChain>(m_setup, m_channels, m_rate_hz, kPiece)),
      m_derived(std::move(derived))
{
}

std::vector<ChannelDescriptor> SignalColumns::channels() const
{
    std::vector<ChannelDescriptor> result = m_derived ? m_derived->channels() : std::vector<ChannelDescriptor>{};
    result.insert(result.end(), m_chain->outputs().begin(), m_chain->outputs().end());
    return result;
}

std::string SignalColumns::basis() const
{
    const std::string derived = m_derived ? m_derived->basis() + "; " : "";
    return derived + "the session's signal setup, run over its stored samples from the first: " + m_setup.text();
}

void SignalColumns::run(std::uint64_t end, std::uint64_t keepFrom, std::vector<std::vector<double>>& kept)
{
    std::vector<std::size_t> all(m_channels.size());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    std::vector<std::vector<double>> stored;
    core::LiveChunk chunk;
    while (m_next < end) {
        const auto count = static_cast<std::size_t>(std::min<std::uint64_t>(kPiece, end - m_next));
        m_store.readChannels(m_session, all, m_next, count, stored);
        SampleBlock block(m_channels.size(), count, static_cast<double>(m_next) / m_rate_hz, 1.0 / m_rate_hz, m_next);
        for (std::size_t c = 0; c < m_channels.size(); ++c) std::ranges::copy(stored[c], block.channel(c).begin());
        m_chain->consume(block);
        m_chain->output()->readNew(m_cursor, chunk);
        for (std::size_t i = 0; i < chunk.sampleCount(); ++i) {
            if (m_next + i < keepFrom) continue;
            for (std::size_t o = 0; o < kept.size(); ++o) kept[o].push_back(chunk.values[o][i]);
        }
        m_next += count;
    }
}

std::vector<std::vector<double>> SignalColumns::read(std::uint64_t first, std::uint64_t count)
{
    if (!m_derived && !m_cached.empty() && first == m_cachedFirst && count == m_cachedCount) return m_cached;
    std::vector<std::vector<double>> columns =
        m_derived ? m_derived->read(first, count) : std::vector<std::vector<double>>{};
    const std::uint64_t end = std::min<std::uint64_t>(first + count, m_store.sampleCount(m_session));
    if (first < m_next) {  // behind the chain: from the session's first sample again
        m_chain = std::make_unique<SignalChain>(m_setup, m_channels, m_rate_hz, kPiece);
        m_cursor = {};
        m_next = 0;
    }
    std::vector<std::vector<double>> signal(m_chain->outputs().size());
    run(end, first, signal);
    for (auto& column : signal) columns.push_back(std::move(column));
    if (!m_derived) {
        m_cachedFirst = first;
        m_cachedCount = count;
        m_cached = columns;
    }
    return columns;
}

std::vector<storage::OverviewPoint> SignalColumns::overview(std::size_t column, std::uint64_t first,
                                                            std::uint64_t count, std::size_t points)
{
    const std::uint64_t total = m_store.sampleCount(m_session);
    const std::uint64_t end = std::min(total, first + std::min(count, total));
    if (end <= first || points == 0 || end - first > kExactLimit) return {};
    std::vector<storage::OverviewPoint> result;
    derived::appendExactOverview(read(first, end - first).at(column), first, points, result);
    return result;
}

std::vector<std::unique_ptr<storage::LaneSource>> recordedSignalLanes(storage::SessionSource& store,
                                                                      std::int64_t session, std::string& problem)
{
    problem.clear();
    std::vector<std::unique_ptr<storage::LaneSource>> lanes;
    const auto summary = store.session(session);
    if (!summary || summary->metadata.signalSetup.empty()) return lanes;
    try {
        auto columns = std::make_shared<SignalColumns>(store, session,
                                                       signalSetupFromJson(summary->metadata.signalSetup), nullptr);
        for (std::size_t c = 0; c < columns->channels().size(); ++c)
            lanes.push_back(std::make_unique<derived::DerivedLane<SignalColumns>>(columns, c));
    } catch (const std::invalid_argument& e) {
        problem = std::string("its filters and math channels are not shown: ") + e.what();
    }
    return lanes;
}

std::unique_ptr<storage::ComputedColumns> withRecordedSignal(storage::SessionSource& store, std::int64_t session,
                                                             std::unique_ptr<storage::ComputedColumns> derived,
                                                             std::string& problem)
{
    problem.clear();
    const auto summary = store.session(session);
    if (!summary || summary->metadata.signalSetup.empty()) return derived;
    try {
        return std::make_unique<SignalColumns>(store, session, signalSetupFromJson(summary->metadata.signalSetup),
                                               std::move(derived));
    } catch (const std::invalid_argument& e) {  // the chain is made before `derived` is taken
        problem = std::string("the session's filters and math channels are left out: ") + e.what();
        return derived;
    }
}

storage::PartColumns recordedSignalOfParts(storage::SessionSource& store, std::vector<std::string>& problems)
{
    return [&store, &problems](std::int64_t part) {
        std::string problem;
        auto columns = withRecordedSignal(store, part, nullptr, problem);
        if (!problem.empty() && std::ranges::find(problems, problem) == problems.end()) problems.push_back(problem);
        return columns;
    };
}

}  // namespace tactiscope::core::signal
