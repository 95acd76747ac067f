// Recorder: queueing on the acquisition thread, batched writes on its own.
#include "core/storage/Recorder.h"

#include "core/SampleBlock.h"
#include "core/storage/DefectRecords.h"
#include "core/text/UtcTime.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace tactiscope::core::storage {

Recorder::Recorder(const std::string& storePath, const SessionMetadata& metadata,
                   std::vector<ChannelDescriptor> channels, double sampleRate_hz, std::uint64_t maxQueuedSamples,
                   const std::vector<std::int64_t>& calibrations)
    : m_sampleRate_hz(sampleRate_hz),
      m_lock(metadata.partOf != 0 ? std::nullopt : std::optional<RecorderLock>(RecorderLock::acquire(storePath))),
      m_store(storePath),
      m_maxQueued(maxQueuedSamples),
      m_channelCount(channels.size())
{
    m_store.refuseIfDamaged();  // a damaged file only gets worse with every page written
    if (m_lock) m_store.markCrashedSessionsInterrupted();
    m_wallStart = std::chrono::system_clock::now();
    m_steadyStart = std::chrono::steady_clock::now();
    m_session = m_store.beginSession(metadata, channels, sampleRate_hz, {{}, text::utcIso8601(m_wallStart), {}});
    m_triggered = !metadata.trigger.empty();
    try {
        for (const std::int64_t calibration : calibrations) m_store.linkCalibration(m_session, calibration);
    } catch (const StorageError&) {
        m_store.endSession(m_session, SessionStatus::Interrupted);  // not left "recording"
        throw;
    }
    // From here on only the writer thread touches m_store, until finish().
    m_writer = std::jthread([this](const std::stop_token& stop) { run(stop); });
}

Recorder::~Recorder()
{
    finish(SessionStatus::Interrupted);
}

void Recorder::consume(const SampleBlock& block)
{
    const std::lock_guard lock(m_mutex);
    if (!m_firstIndex) {
        m_firstIndex = block.firstSampleIndex();
        m_firstTime_s = block.t0_s();
        if (m_firstSampleWatch) m_firstSampleWatch(*m_firstIndex);
    }
    m_consumedEnd = block.endSampleIndex() - *m_firstIndex;
    if (!block.empty()) m_consumedUntil_s = block.timeAt_s(block.sampleCount() - 1);
    if (m_finished || !m_stats.error.empty() || m_queuedSamples + block.sampleCount() > m_maxQueued) {
        m_stats.samplesDropped += block.sampleCount();
        return;
    }
    m_queue.push_back(block);
    // Unsigned arithmetic wraps, so adding −first subtracts it exactly.
    m_queue.back().rebase(-m_firstTime_s, std::uint64_t{0} - *m_firstIndex);
    m_queuedSamples += block.sampleCount();
    m_wake.notify_one();
}

void Recorder::addEvents(std::vector<SessionEvent> events)
{
    const std::lock_guard lock(m_mutex);
    m_queuedEvents.insert(m_queuedEvents.end(), std::make_move_iterator(events.begin()),
                          std::make_move_iterator(events.end()));
    m_wake.notify_one();
}

void Recorder::addReadings(std::vector<SessionReading> readings)
{
    const std::lock_guard lock(m_mutex);
    m_queuedReadings.insert(m_queuedReadings.end(), std::make_move_iterator(readings.begin()),
                            std::make_move_iterator(readings.end()));
    m_wake.notify_one();
}

void Recorder::setClockMapping(std::string clockJson)
{
    const std::lock_guard lock(m_mutex);
    m_queuedClock = std::move(clockJson);
    m_wake.notify_one();
}

void Recorder::setSignalSetup(std::string setupJson)
{
    const std::lock_guard lock(m_mutex);
    m_queuedSignal = std::move(setupJson);
    m_wake.notify_one();
}

void Recorder::addZero(std::uint64_t streamIndex, std::string valuesJson)
{
    const std::lock_guard lock(m_mutex);
    m_queuedZeros.push_back({streamIndex, std::move(valuesJson)});
    m_wake.notify_one();
}

double Recorder::sessionTime_s() const
{
    const std::lock_guard lock(m_mutex);
    return m_consumedEnd == 0 ? 0.0 : static_cast<double>(m_consumedEnd - 1) / m_sampleRate_hz;
}

void Recorder::markLostUntil(double sessionTime_s)
{
    const std::lock_guard lock(m_mutex);
    const double end = std::ceil(sessionTime_s * m_sampleRate_hz);
    if (end > static_cast<double>(m_consumedEnd)) m_consumedEnd = static_cast<std::uint64_t>(end);
}

void Recorder::addChannels(const std::vector<ChannelDescriptor>& all)
{
    const std::lock_guard lock(m_mutex);
    if (all.size() <= m_channelCount) return;
    m_queuedChannels.insert(m_queuedChannels.end(), all.begin() + static_cast<std::ptrdiff_t>(m_channelCount),
                            all.end());
    m_channelCount = all.size();
}

std::optional<double> Recorder::consumedUntil_s() const
{
    const std::lock_guard lock(m_mutex);
    return m_consumedUntil_s;
}

double Recorder::sessionTimeOf(double acquisitionTime_s) const
{
    const std::lock_guard lock(m_mutex);
    return acquisitionTime_s - m_firstTime_s;
}

std::optional<double> Recorder::acquisitionOrigin_s() const
{
    const std::lock_guard lock(m_mutex);
    return m_firstIndex ? std::optional<double>(m_firstTime_s) : std::nullopt;
}

RecorderStats Recorder::stats() const
{
    const std::lock_guard lock(m_mutex);
    return m_stats;
}

void Recorder::run(const std::stop_token& stop)
{
    std::unique_lock lock(m_mutex);
    while (!stop.stop_requested()) {
        // Wake at once for a full queue, else gather a commit interval's worth.
        m_wake.wait_for(lock, stop, kCommitInterval, [this] { return m_queuedSamples * 2 > m_maxQueued; });
        writeQueued(lock);
    }
    writeQueued(lock);
}

void Recorder::writeQueued(std::unique_lock<std::mutex>& lock)
{
    // Zeros wait for the first block, which fixes the session's sample 0.
    const bool zeros = !m_queuedZeros.empty() && m_firstIndex;
    if ((m_queue.empty() && m_queuedEvents.empty() && m_queuedReadings.empty() && !zeros && !m_queuedClock &&
         !m_queuedSignal && m_queuedChannels.empty()) ||
        !m_stats.error.empty())
        return;
    const std::vector<ChannelDescriptor> channels = std::exchange(m_queuedChannels, {});
    // The samples written before a channel came are holes in it, as are a
    // block's samples in the channels it does not hold yet.
    const std::size_t channelCount = m_channelCount;
    const std::uint64_t writtenBefore = m_stats.samplesWritten;
    const std::optional<std::string> clock = std::exchange(m_queuedClock, std::nullopt);
    const std::optional<std::string> signal = std::exchange(m_queuedSignal, std::nullopt);
    std::vector<SessionZero> zeroRecords;
    if (zeros) {
        zeroRecords = std::move(m_queuedZeros);
        m_queuedZeros.clear();
        for (auto& zero : zeroRecords) zero.firstIndex -= std::min(zero.firstIndex, *m_firstIndex);
    }
    std::vector<SampleBlock> batch(std::make_move_iterator(m_queue.begin()), std::make_move_iterator(m_queue.end()));
    m_queue.clear();
    std::vector<SessionEvent> events = std::move(m_queuedEvents);
    m_queuedEvents.clear();
    std::vector<SessionReading> readings = std::move(m_queuedReadings);
    m_queuedReadings.clear();
    const std::uint64_t samples = m_queuedSamples;
    m_queuedSamples = 0;
    lock.unlock();  // the acquisition keeps queueing while the disk works
    std::string error;
    try {
        // First: blocks from before they came hold them as holes.
        if (!channels.empty()) m_store.addChannels(m_session, channels);
        m_store.appendBlocks(m_session, batch);
        if (!events.empty()) m_store.addEvents(m_session, events);
        for (const auto& reading : readings) m_store.addReading(m_session, reading);
        for (const auto& zero : zeroRecords) m_store.addZero(m_session, zero);
        if (clock) m_store.setClockMapping(m_session, *clock);
        if (signal) m_store.setSignalSetup(m_session, *signal);
    } catch (const StorageError& e) {
        error = e.what();
    }
    std::vector<std::uint64_t> holes(channelCount);  // counted before the lock is taken again
    for (std::size_t c = channelCount - channels.size(); c < channelCount; ++c) holes[c] = writtenBefore;
    for (const auto& block : batch)
        for (std::size_t c = 0; c < channelCount; ++c)
            holes[c] += c < block.channelCount() ? static_cast<std::uint64_t>(std::ranges::count_if(
                                                       block.channel(c), [](double v) { return std::isnan(v); }))
                                                 : block.sampleCount();
    lock.lock();
    if (error.empty()) {
        m_stats.holes.resize(std::max(m_stats.holes.size(), holes.size()));
        for (std::size_t c = 0; c < holes.size(); ++c) m_stats.holes[c] += holes[c];
        m_stats.samplesWritten += samples;
        m_stats.eventsWritten += events.size();
        m_stats.readingsWritten += readings.size();
        ++m_stats.commits;
    } else {
        m_stats.error = "recording stopped: " + error + "; everything recorded before was kept";
        m_stats.samplesDropped += samples + m_queuedSamples;
        m_queue.clear();
        m_queuedSamples = 0;
    }
}

// Now on the host's wall clock, unless it was set (back, or forward by more
// than a second) while recording: then the start plus the time the
// recording lasted, with a note, so that a session never ends before it
// began nor is dated by a step the recording did not take.
std::chrono::system_clock::time_point Recorder::endOnTheWallClock()
{
    const auto now = std::chrono::system_clock::now();
    const auto lasted = std::chrono::steady_clock::now() - m_steadyStart;
    const double step_s = std::chrono::duration<double>((now - m_wallStart) - lasted).count();
    if (std::abs(step_s) <= 1.0) return now;
    char text[200];
    std::snprintf(text, sizeof text,
                  "the host's clock was set %s by %.1f s during this recording: its end is dated by its start and "
                  "how long it lasted",
                  step_s < 0.0 ? "back" : "forward", std::abs(step_s));
    const double end_s = static_cast<double>(m_consumedEnd) / m_sampleRate_hz;
    try {
        m_store.addEvents(m_session, std::vector{noteRecord(end_s, text)});
    } catch (const StorageError& e) {
        if (m_stats.error.empty()) m_stats.error = e.what();
    }
    return m_wallStart + std::chrono::duration_cast<std::chrono::system_clock::duration>(lasted);
}

RecorderStats Recorder::finish(SessionStatus status, const std::optional<VerdictDecision>& verdict,
                               const std::string& unjudged)
{
    {
        const std::lock_guard lock(m_mutex);
        if (m_finished) return m_stats;
        m_finished = true;  // consume() drops from here on
    }
    m_writer.request_stop();
    m_writer.join();  // writes what was queued
    const std::lock_guard lock(m_mutex);
    const auto now = endOnTheWallClock();
    // A triggered session begins with its first sample, which came before
    // the trigger was seen (its pre-trigger seconds; a board's lines held
    // while they were timed): dated back from its end, which is about now,
    // before the gap to its end is measured against how long it lasted.
    if (m_triggered && m_firstIndex) {
        const double length_s = static_cast<double>(m_consumedEnd) / m_sampleRate_hz;
        try {
            m_store.setStartedUtc(m_session,
                                  text::utcIso8601(now - std::chrono::duration_cast<std::chrono::milliseconds>(
                                                             std::chrono::duration<double>(length_s))));
        } catch (const StorageError& e) {
            if (m_stats.error.empty()) m_stats.error = e.what();
        }
    }
    // What was not stored (lost by the device at the end, over the memory
    // bound, or after a write failed) is a gap to the end, so the session
    // shows what it lacks. A gap is one small row, which a disk too full for
    // another chunk usually still takes, as it takes the end mark.
    try {
        m_store.markLostUntil(m_session, m_consumedEnd);
    } catch (const StorageError& e) {
        if (m_stats.error.empty()) m_stats.error = e.what();
        m_stats.error += "; the samples not stored could not be marked as lost in the store";
    }
    try {
        m_store.endSession(m_session, m_stats.error.empty() ? status : SessionStatus::Interrupted,
                           text::utcIso8601(now));
        if (verdict) m_store.decideVerdict(m_session, *verdict);
        if (!unjudged.empty()) m_store.markUnjudged(m_session, unjudged);
    } catch (const StorageError& e) {
        // The samples are committed; only the end mark is missing.
        if (m_stats.error.empty()) m_stats.error = e.what();
    }
    return m_stats;
}

}  // namespace tactiscope::core::storage
