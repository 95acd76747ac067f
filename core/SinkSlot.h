// A place for one sink on a running acquisition, whose occupant can change
// while blocks flow. The acquisition takes its sinks before it starts; a
// processor rebuilt for another sensor profile goes into the slot instead,
// and the next block reaches it. Every block goes to exactly one occupant
// (or none), never half to each.
#pragma once

#include "core/BlockSink.h"

#include <memory>
#include <mutex>

namespace tactiscope::core {

class SinkSlot final : public BlockSink {
public:
    // Any thread; nullptr empties the slot. Waits for a block being consumed
    // by the old occupant, so once set() returns the old one gets no more.
    void set(std::shared_ptr<BlockSink> sink)
    {
        const std::lock_guard lock(m_mutex);
        m_sink = std::move(sink);
    }

    void consume(const SampleBlock& block) override
    {
        const std::lock_guard lock(m_mutex);
        if (m_sink) m_sink->consume(block);
    }

private:
    std::mutex m_mutex;
    std::shared_ptr<BlockSink> m_sink;
};

}  // namespace tactiscope::core
