// ProbeDetector: one PairDetector per adjacent cantilever pair.
#include "core/detector/ProbeDetector.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::detector {

ProbeOutput combinePairs(std::span<const DetectorOutput* const> pairs, double threshold)
{
    ProbeOutput result;
    result.combined = *pairs.front();
    for (std::size_t p = 1; p < pairs.size(); ++p) {
        const DetectorOutput& o = *pairs[p];
        if (o.rab > result.combined.rab) {
            result.combined.rab = o.rab;
            result.combined.lagAb = o.lagAb;
            result.pairAb = p;
        }
        if (o.rba > result.combined.rba) {
            result.combined.rba = o.rba;
            result.combined.lagBa = o.lagBa;
            result.pairBa = p;
        }
    }
    result.combined.decision = decide(result.combined.rab, result.combined.rba, threshold);
    return result;
}

ProbeDetector::ProbeDetector(const DetectorParameters& parameters, std::vector<std::size_t> cantileverChannels,
                             KernelVariant variant)
    : m_channels(std::move(cantileverChannels))
{
    if (m_channels.size() < 2) throw std::invalid_argument("a probe needs at least two cantilevers");
    std::vector<std::size_t> sorted = m_channels;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw std::invalid_argument("each cantilever needs its own channel");
    for (std::size_t p = 0; p + 1 < m_channels.size(); ++p) m_pairs.emplace_back(parameters, variant);
    m_pairOutputs.resize(m_pairs.size());
    m_row.resize(m_pairs.size());
}

std::span<const ProbeOutput> ProbeDetector::push(const SampleBlock& block)
{
    const double dt = parameters().sampleInterval_s;
    if (std::abs(block.dt_s() - dt) > 1e-3 * dt)
        throw std::invalid_argument("block sample interval differs from the detector's");
    for (std::size_t c : m_channels) {
        if (c >= block.channelCount()) throw std::invalid_argument("block lacks a cantilever channel");
    }
    const std::size_t n = block.sampleCount();
    for (std::size_t p = 0; p < m_pairs.size(); ++p) {
        m_pairOutputs[p].resize(n);
        m_pairs[p].process(block.channel(m_channels[p]), block.channel(m_channels[p + 1]), m_pairOutputs[p]);
    }
    m_outputs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t p = 0; p < m_pairs.size(); ++p) m_row[p] = &m_pairOutputs[p][i];
        m_outputs[i] = combinePairs(m_row, parameters().threshold);
        m_outputs[i].t_s = block.timeAt_s(i);
    }
    return m_outputs;
}

void ProbeDetector::reset()
{
    for (auto& pair : m_pairs) pair.reset();
}

std::vector<PairDetector::Snapshot> ProbeDetector::snapshot() const
{
    std::vector<PairDetector::Snapshot> result;
    for (const auto& pair : m_pairs) result.push_back(pair.snapshot());
    return result;
}

void ProbeDetector::restore(const std::vector<PairDetector::Snapshot>& snapshot)
{
    if (snapshot.size() != m_pairs.size()) throw std::invalid_argument("snapshot is of a probe with other cantilevers");
    for (std::size_t p = 0; p < m_pairs.size(); ++p) m_pairs[p].restore(snapshot[p]);
}

}  // namespace tactiscope::core::detector
