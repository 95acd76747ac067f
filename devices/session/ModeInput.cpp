// The modes' input: the block as it came, or its filtered copy.
#include "devices/session/ModeInput.h"

namespace tactiscope::devices::session {

void ModeInput::setChain(std::shared_ptr<const core::signal::SignalChain> chain)
{
    const std::lock_guard lock(m_mutex);
    m_chain = std::move(chain);
}

void ModeInput::consume(const core::SampleBlock& block)
{
    const std::lock_guard lock(m_mutex);
    const core::SampleBlock* read = &block;
    if (m_chain) {
        m_chain->filteredCopy(block, m_filtered);
        read = &m_filtered;
    }
    for (const auto& sink : m_sinks) sink->consume(*read);
}

}  // namespace tactiscope::devices::session
