// TriggerGate: the trigger's rules per sample, the held blocks, and each
// session's samples cut to its span for its recorder.
#include "devices/session/TriggerGate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tactiscope::devices::session {
namespace {

// Samples [from, to) of `block` (stream indices) as a block of their own.
core::SampleBlock slice(const core::SampleBlock& block, std::uint64_t from, std::uint64_t to)
{
    if (from <= block.firstSampleIndex() && to >= block.endSampleIndex()) return block;
    const auto begin = static_cast<std::size_t>(from - block.firstSampleIndex());
    const auto count = static_cast<std::size_t>(to - from);
    core::SampleBlock part(block.channelCount(), count, block.timeAt_s(begin), block.dt_s(), from, block.sequence());
    for (std::size_t c = 0; c < block.channelCount(); ++c) {
        const auto source = block.channel(c).subspan(begin, count);
        std::copy(source.begin(), source.end(), part.channel(c).begin());
    }
    return part;
}

}  // namespace

void TriggerGate::arm(const core::trigger::TriggerSettings& settings, QuantityReader reader, double sampleRate_hz,
                      double maxBacklog_s)
{
    core::trigger::TriggerMachine machine(settings, sampleRate_hz);
    const std::lock_guard lock(m_mutex);
    m_maxBacklog = machine.preSamples() + static_cast<std::uint64_t>(std::ceil(maxBacklog_s * sampleRate_hz));
    m_machine.emplace(std::move(machine));
    m_rate_hz = sampleRate_hz;
    m_reader = std::move(reader);
    m_held.clear();
    m_sessions.clear();
    m_recorder.reset();
    m_finished.reset();
}

void TriggerGate::disarm()
{
    const std::lock_guard lock(m_mutex);
    m_machine.reset();
    m_held.clear();
    m_sessions.clear();
    m_recorder.reset();
    m_finished.reset();
}

void TriggerGate::replaceReader(QuantityReader reader)
{
    const std::lock_guard lock(m_mutex);
    m_reader = std::move(reader);
}

bool TriggerGate::armed() const
{
    const std::lock_guard lock(m_mutex);
    return m_machine.has_value();
}

TriggerStatus TriggerGate::status() const
{
    const std::lock_guard lock(m_mutex);
    if (!m_machine) return {};
    return {m_machine->state(), m_machine->sessionsCut(), m_machine->valueSeen()};
}

std::optional<TriggeredSession> TriggerGate::pendingStart() const
{
    const std::lock_guard lock(m_mutex);
    if (m_recorder || m_finished || m_sessions.empty()) return std::nullopt;
    return m_sessions.front();
}

std::size_t TriggerGate::waiting() const
{
    const std::lock_guard lock(m_mutex);
    return m_sessions.size() - (m_recorder && !m_sessions.empty() ? 1 : 0);
}

std::optional<double> TriggerGate::reachBack_s() const
{
    const std::lock_guard lock(m_mutex);
    if (!m_machine) return std::nullopt;
    const auto samples = [this](std::uint64_t n) { return static_cast<double>(n) / m_rate_hz; };
    if (!m_sessions.empty() && !m_recorder) {
        const auto& pending = m_sessions.front();
        return pending.triggerTime_s - samples(pending.span.trigger - pending.span.first);
    }
    if (m_held.empty()) return -std::numeric_limits<double>::infinity();
    return m_held.back().endTime_s() - samples(m_machine->preSamples());
}

void TriggerGate::attach(std::shared_ptr<core::storage::Recorder> recorder)
{
    const std::lock_guard lock(m_mutex);
    if (m_sessions.empty() || m_finished) return;
    m_recorder = std::move(recorder);
    if (m_recorder) m_recorder->addChannels(m_grownTo);
    m_forwardedUntil = m_sessions.front().span.first;
    forward();
    trim();
}

void TriggerGate::channelsGrew(const std::vector<core::ChannelDescriptor>& all)
{
    const std::lock_guard lock(m_mutex);
    m_grownTo = all;
    if (m_recorder) m_recorder->addChannels(all);
}

std::optional<TriggerGate::Finished> TriggerGate::takeFinished()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_finished, std::nullopt);
}

std::shared_ptr<core::storage::Recorder> TriggerGate::detach()
{
    const std::lock_guard lock(m_mutex);
    if (m_recorder && !m_sessions.empty()) m_sessions.pop_front();  // what it had is its whole session
    return std::exchange(m_recorder, nullptr);
}

void TriggerGate::consume(const core::SampleBlock& block)
{
    if (block.empty()) return;
    const std::lock_guard lock(m_mutex);
    if (!m_machine) return;
    m_reader.read(block, m_values);
    for (std::size_t s = 0; s < block.sampleCount(); ++s) {
        const auto step = m_machine->push(block.firstSampleIndex() + s, m_values[s]);
        if (step.started) {
            const auto trigger = static_cast<std::size_t>(step.started->trigger - block.firstSampleIndex());
            m_sessions.push_back({*step.started, block.timeAt_s(trigger)});
        }
        if (step.ended) {
            // By its trigger: its first sample may have moved on (a backlog overrun).
            const auto open = std::ranges::find(m_sessions, step.ended->trigger,
                                                [](const TriggeredSession& t) { return t.span.trigger; });
            if (open != m_sessions.end()) open->span.end = step.ended->end;
        }
    }
    m_held.push_back(block);
    forward();
    trim();
}

// The front session's held samples not yet passed on go to its recorder;
// once its last one has, the recorder is handed back.
void TriggerGate::forward()
{
    if (!m_recorder || m_sessions.empty()) return;
    const auto& front = m_sessions.front();
    const std::uint64_t end = front.span.end > 0 ? front.span.end : UINT64_MAX;
    for (const auto& block : m_held) {
        const std::uint64_t from = std::max(m_forwardedUntil, block.firstSampleIndex());
        const std::uint64_t to = std::min(end, block.endSampleIndex());
        if (from >= to) continue;
        m_recorder->consume(slice(block, from, to));
        m_forwardedUntil = to;
    }
    if (front.span.end > 0 && m_forwardedUntil >= front.span.end) {
        m_finished = Finished{front, std::exchange(m_recorder, nullptr)};
        m_sessions.pop_front();
    }
}

// Blocks are held only as long as a session may still need them: a
// pending one from its first sample, an open one from what its recorder
// has not had yet, otherwise the pre-trigger time; and never beyond the
// backlog bound (a session that loses its oldest held samples starts later).
void TriggerGate::trim()
{
    if (m_held.empty()) return;
    const std::uint64_t newest = m_held.back().endSampleIndex();
    std::uint64_t keepFrom = newest - std::min(newest, m_machine->preSamples());
    if (!m_sessions.empty()) keepFrom = m_recorder ? m_forwardedUntil : m_sessions.front().span.first;
    keepFrom = std::max(keepFrom, newest - std::min(newest, m_maxBacklog));
    while (!m_held.empty() && m_held.front().endSampleIndex() <= keepFrom) m_held.pop_front();
    if (!m_sessions.empty() && !m_recorder && !m_held.empty())
        m_sessions.front().span.first = std::max(m_sessions.front().span.first, m_held.front().firstSampleIndex());
}

}  // namespace tactiscope::devices::session
