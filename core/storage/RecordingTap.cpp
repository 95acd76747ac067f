// RecordingTap: a mutex around the recorder pointer; Recorder::consume only
// queues, so holding it while forwarding costs the acquisition nothing.
#include "core/storage/RecordingTap.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tactiscope::core::storage {

namespace {

// The samples of `block` from `first` on, as a block of their own.
SampleBlock tailOf(const SampleBlock& block, std::size_t first)
{
    SampleBlock tail(block.channelCount(), block.sampleCount() - first, block.timeAt_s(first), block.dt_s(),
                     block.firstSampleIndex() + first, block.sequence());
    for (std::size_t c = 0; c < block.channelCount(); ++c)
        std::ranges::copy(block.channel(c).subspan(first), tail.channel(c).begin());
    return tail;
}

}  // namespace

void RecordingTap::attach(std::shared_ptr<Recorder> recorder, std::optional<double> from_s)
{
    const std::lock_guard lock(m_mutex);
    m_recorder = std::move(recorder);
    m_from_s = from_s;
}

std::shared_ptr<Recorder> RecordingTap::detach()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_recorder, nullptr);
}

void RecordingTap::consume(const SampleBlock& block)
{
    const std::lock_guard lock(m_mutex);
    if (!m_recorder) return;
    if (m_from_s) {
        // A sample at the start instant belongs in, whatever the rounding.
        const double from_s = *m_from_s - 1e-6 * block.dt_s();
        const double first = std::max(0.0, std::ceil((from_s - block.t0_s()) / block.dt_s()));
        if (first >= static_cast<double>(block.sampleCount())) return;
        m_from_s.reset();
        if (first > 0.0) {
            m_recorder->consume(tailOf(block, static_cast<std::size_t>(first)));
            return;
        }
    }
    m_recorder->consume(block);
}

}  // namespace tactiscope::core::storage
