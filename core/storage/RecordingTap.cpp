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

// Samples [first, first + count) of `block`, as a block of their own.
SampleBlock sliceOf(const SampleBlock& block, std::size_t first, std::size_t count)
{
    SampleBlock slice(block.channelCount(), count, block.timeAt_s(first), block.dt_s(),
                      block.firstSampleIndex() + first, block.sequence());
    for (std::size_t c = 0; c < block.channelCount(); ++c)
        std::ranges::copy(block.channel(c).subspan(first, count), slice.channel(c).begin());
    return slice;
}

// The first sample of `block` at or after `time_s` (a sample at it, whatever
// the rounding, counts as at it); the sample count when none is.
std::size_t firstAtOrAfter(const SampleBlock& block, double time_s)
{
    const double first = std::ceil((time_s - 1e-6 * block.dt_s() - block.t0_s()) / block.dt_s());
    return static_cast<std::size_t>(std::clamp(first, 0.0, static_cast<double>(block.sampleCount())));
}

}  // namespace

void RecordingTap::attach(std::shared_ptr<Recorder> recorder, RecordingStartFinder start,
                          std::optional<double> length_s)
{
    const std::lock_guard lock(m_mutex);
    m_length_s = length_s;
    m_until_s.reset();
    m_complete = false;
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

bool RecordingTap::complete() const
{
    const std::lock_guard lock(m_mutex);
    return m_complete;
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
    if (m_complete) return;
    std::size_t first = 0;
    if (m_from_s) {
        first = firstAtOrAfter(block, *m_from_s);
        if (first == block.sampleCount()) return;
        m_from_s.reset();
    }
    std::size_t end = block.sampleCount();
    if (m_length_s) {
        // A sample is in when most of its period is: a length holds its
        // whole number of periods whether the rate was measured a little
        // high or a little low (2 s of a timed 100 Hz board: 200 samples).
        if (!m_until_s) m_until_s = block.timeAt_s(first) + *m_length_s;
        const double cut_s = *m_until_s - 0.5 * block.dt_s();
        end = firstAtOrAfter(block, cut_s);
        m_complete = end < block.sampleCount() || block.endTime_s() >= cut_s - 1e-6 * block.dt_s();
        if (end <= first) return;
    }
    m_recorder->consume(first == 0 && end == block.sampleCount() ? block : sliceOf(block, first, end - first));
}

}  // namespace tactiscope::core::storage
