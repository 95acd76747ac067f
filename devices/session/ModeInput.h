// What the modes' processors read: the device's blocks as they come, or,
// when the session's signal setup says the mode analyses the filtered
// channels, with each filtered channel as the signal chain filtered it
// (core/signal/SignalChain.h). One sink before every mode's slot, after
// the chain, so a block is filtered once whichever modes read it.
//
// Threading: consume() on the acquisition thread; setChain() from the owner.
#pragma once

#include "core/BlockSink.h"
#include "core/SampleBlock.h"
#include "core/signal/SignalChain.h"

#include <memory>
#include <mutex>
#include <vector>

namespace tactiscope::devices::session {

class ModeInput final : public core::BlockSink {
public:
    // The modes' slots, before the acquisition starts.
    void add(std::shared_ptr<core::BlockSink> sink) { m_sinks.push_back(std::move(sink)); }
    // The chain whose filtered channels the modes read; null: the blocks as they come.
    void setChain(std::shared_ptr<const core::signal::SignalChain> chain);

    void consume(const core::SampleBlock& block) override;

private:
    std::vector<std::shared_ptr<core::BlockSink>> m_sinks;
    std::mutex m_mutex;
    std::shared_ptr<const core::signal::SignalChain> m_chain;
    core::SampleBlock m_filtered;  // reused
};

}  // namespace tactiscope::devices::session
