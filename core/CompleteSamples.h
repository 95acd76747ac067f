// A sink that passes on only the samples whose watched channels all hold a
// value. A NaN (a hole in one channel: a text board printed "nan") leaves
// its sample out, so the processor behind sees a gap in the sample index
// and begins again after it, as after a lost sample, rather than carrying
// the NaN through its filters for the rest of the session. The store and
// the display take every sample, holes and all.
#pragma once

#include "core/BlockSink.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace tactiscope::core {

class CompleteSamples final : public BlockSink {
public:
    // `channels`: the indices a processor reads; none passes every block as it is.
    CompleteSamples(std::shared_ptr<BlockSink> inner, std::vector<std::size_t> channels);

    void consume(const SampleBlock& block) override;

private:
    bool complete(const SampleBlock& block, std::size_t sample) const;

    std::shared_ptr<BlockSink> m_inner;
    std::vector<std::size_t> m_channels;
};

}  // namespace tactiscope::core
