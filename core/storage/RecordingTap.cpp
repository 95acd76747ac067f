// RecordingTap: a mutex around the recorder pointer, the blocks held while
// the start is not known, and the cut at it; Recorder::consume only
// queues, so holding the mutex while forwarding costs the acquisition
// nothing.
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

void RecordingTap::attach(std::shared_ptr<Recorder> recorder, RecordingStartFinder start)
{
    const std::lock_guard lock(m_mutex);
    m_recorder = std::move(recorder);
    if (m_recorder) m_recorder->addChannels(m_grownTo);
    m_finder = std::move(start);
    m_held.clear();
    m_heldValues = 0;
    m_from_s.reset();
}

void RecordingTap::channelsGrew(const std::vector<ChannelDescriptor>& all)
{
    const std::lock_guard lock(m_mutex);
    m_grownTo = all;
    if (m_recorder) m_recorder->addChannels(all);
}

std::shared_ptr<Recorder> RecordingTap::detach()
{
    const std::lock_guard lock(m_mutex);
    if (m_recorder && m_finder && !m_held.empty()) release(m_finder(m_held.back().endTime_s(), true));
    m_finder = nullptr;
    m_held.clear();
    m_heldValues = 0;
    return std::exchange(m_recorder, nullptr);
}

void RecordingTap::consume(const SampleBlock& block)
{
    const std::lock_guard lock(m_mutex);
    if (!m_recorder) return;
    if (!m_finder) {
        record(block);
        return;
    }
    m_held.push_back(block);
    m_heldValues += block.sampleCount() * block.channelCount();
    const bool mustAnswer = m_heldValues >= m_mostHeldValues;
    if (const auto start = m_finder(block.endTime_s(), mustAnswer); start.known || mustAnswer) release(start);
}

void RecordingTap::release(const RecordingStart& start)
{
    m_finder = nullptr;
    m_from_s = start.from_s;
    for (const auto& block : m_held) record(block);
    m_held.clear();
    m_heldValues = 0;
}

void RecordingTap::record(const SampleBlock& block)
{
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
