// CompleteSamples: each run of complete samples as a block of its own.
#include "core/CompleteSamples.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tactiscope::core {

CompleteSamples::CompleteSamples(std::shared_ptr<BlockSink> inner, std::vector<std::size_t> channels)
    : m_inner(std::move(inner)),
      m_channels(std::move(channels))
{
}

bool CompleteSamples::complete(const SampleBlock& block, std::size_t sample) const
{
    return std::ranges::none_of(
        m_channels, [&](std::size_t c) { return c < block.channelCount() && std::isnan(block.channel(c)[sample]); });
}

void CompleteSamples::consume(const SampleBlock& block)
{
    const std::size_t n = block.sampleCount();
    std::size_t from = 0;
    while (from < n && complete(block, from)) ++from;
    if (from == n) {  // the usual case: no hole, no copy
        m_inner->consume(block);
        return;
    }
    from = 0;
    while (from < n) {
        while (from < n && !complete(block, from)) ++from;
        std::size_t to = from;
        while (to < n && complete(block, to)) ++to;
        if (to > from) {
            SampleBlock run(block.channelCount(), to - from, block.timeAt_s(from), block.dt_s(),
                            block.firstSampleIndex() + from, block.sequence());
            for (std::size_t c = 0; c < block.channelCount(); ++c)
                std::ranges::copy(block.channel(c).subspan(from, to - from), run.channel(c).begin());
            m_inner->consume(run);
        }
        from = to;
    }
}

}  // namespace tactiscope::core
