// LimitAlarms: each limit's watch over its quantity's samples.
#include "devices/session/LimitAlarms.h"

#include <utility>

namespace tactiscope::devices::session {

void LimitAlarms::set(std::vector<Watched> watched, double sampleRate_hz)
{
    std::vector<Watch> watches;
    for (auto& w : watched) watches.push_back({core::trigger::LimitWatch(w.limit, sampleRate_hz), std::move(w.reader)});
    const std::lock_guard lock(m_mutex);
    m_watches = std::move(watches);
    m_changes.clear();
}

void LimitAlarms::replaceReaders(std::vector<QuantityReader> readers)
{
    const std::lock_guard lock(m_mutex);
    for (std::size_t i = 0; i < m_watches.size() && i < readers.size(); ++i)
        m_watches[i].reader = std::move(readers[i]);
}

void LimitAlarms::consume(const core::SampleBlock& block)
{
    if (block.empty()) return;
    const std::lock_guard lock(m_mutex);
    for (auto& w : m_watches) {
        w.reader.read(block, m_values);
        for (std::size_t s = 0; s < block.sampleCount(); ++s) {
            m_step.clear();
            w.watch.push(block.firstSampleIndex() + s, m_values[s], m_step);
            for (const auto& change : m_step)
                m_changes.push_back({w.watch.spec(), w.reader.unit(), change, block.timeAt_s(s)});
        }
    }
}

std::vector<LimitAlarm> LimitAlarms::take()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_changes, {});
}

}  // namespace tactiscope::devices::session
