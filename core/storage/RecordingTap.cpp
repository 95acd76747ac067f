// RecordingTap: a mutex around the recorder pointer; Recorder::consume only
// queues, so holding it while forwarding costs the acquisition nothing.
#include "core/storage/RecordingTap.h"

#include <utility>

namespace tactiscope::core::storage {

void RecordingTap::attach(std::shared_ptr<Recorder> recorder)
{
    const std::lock_guard lock(m_mutex);
    m_recorder = std::move(recorder);
}

std::shared_ptr<Recorder> RecordingTap::detach()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_recorder, nullptr);
}

void RecordingTap::consume(const SampleBlock& block)
{
    const std::lock_guard lock(m_mutex);
    if (m_recorder) m_recorder->consume(block);
}

}  // namespace tactiscope::core::storage
