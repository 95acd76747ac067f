// SessionBounds: the rules a stored session's counts, indices and gaps keep.
#include "core/storage/SessionBounds.h"

#include "core/NumberRanges.h"
#include "core/storage/Database.h"
#include "core/text/NumberFormat.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::storage {

void SessionBounds::damaged(const std::string& what) const
{
    throw StoreInputError(m_store + ": the store is damaged: in session " + std::to_string(m_session) + ", " + what +
                          "; its samples cannot be read");
}

// Lost samples in `seconds`: what that time holds at the session's rate,
// twice over, plus two seconds of it.
double SessionBounds::mostLost(double seconds) const
{
    return 2.0 * std::max(0.0, seconds) * m_rate_hz + 2.0 * m_rate_hz;
}

void SessionBounds::session(double duration_s, std::int64_t channels, double lowestRate_hz, double highestRate_hz)
{
    if (channels == 0) damaged("it has no channel rows");
    if (!kSampleRateRange.holds(lowestRate_hz) || !kSampleRateRange.holds(highestRate_hz))
        damaged("a channel's sample rate of " + text::formatShortest(lowestRate_hz) + " … " +
                text::formatShortest(highestRate_hz) + " Hz is not " + kSampleRateRange.text());
    m_duration_s = std::isfinite(duration_s) ? std::max(0.0, duration_s) : 0.0;
    m_channels = channels;
    m_rate_hz = highestRate_hz;
}

void SessionBounds::chunk(std::int64_t first, std::int64_t count, std::int64_t bytes, double time_s)
{
    const std::string which = "the chunk at sample " + std::to_string(first);
    if (first < 0) damaged("a chunk starts at sample " + std::to_string(first));
    if (count < 1 || count > kMostChunkSamples) damaged(which + " says it holds " + std::to_string(count) + " samples");
    if (bytes != count * m_channels * 4)
        damaged(which + " says it holds " + std::to_string(count) + " samples but has " + std::to_string(bytes) +
                " bytes");
    if (!std::isfinite(time_s)) damaged(which + " has no time");
    if (m_chunks == 0) m_firstTime_s = time_s;
    if (first < m_chunkEnd) damaged(which + " overlaps the one before");
    // (The first chunk's samples before it: what its time from the
    // session's start allows.)
    const double allowed = m_chunks > 0 ? mostLost(time_s - m_chunkEndTime_s) : mostLost(time_s);
    if (static_cast<double>(first - m_chunkEnd) > allowed)
        damaged(which + " comes " + std::to_string(first - m_chunkEnd) +
                " samples after the one before it, more than its time allows");
    m_chunkEnd = first + count;
    m_chunkEndTime_s = time_s + static_cast<double>(count) / m_rate_hz;
    m_covered += count;
    ++m_chunks;
}

void SessionBounds::gap(std::int64_t first, std::int64_t count)
{
    // A gap runs at most to the session's end: the last chunk plus what its
    // duration from start to stop leaves (a probe lost before the stop).
    const double mostEnd =
        static_cast<double>(m_chunkEnd) + mostLost(m_duration_s - (m_chunkEndTime_s - m_firstTime_s));
    if (first < 0 || count < 1)
        damaged("a gap at sample " + std::to_string(first) + " of " + std::to_string(count) + " samples");
    if (static_cast<double>(first) + static_cast<double>(count) > mostEnd)
        damaged("a gap of " + std::to_string(count) + " samples at sample " + std::to_string(first) +
                " runs past the session's end");
    m_gapsFrom = first + 1;
    m_covered += count;
    m_gapEnd = std::max(m_gapEnd, first + count);
}

void SessionBounds::whole() const
{
    // Every sample up to the last is in a chunk or a gap: the recorder
    // writes a gap for every sample it lost. Samples in neither are a chunk
    // deleted (or moved) by hand; read, they were NaN rows said to be
    // "0 lost".
    const std::int64_t end = std::max(m_chunkEnd, m_gapEnd);
    if (m_covered < end)
        damaged(std::to_string(end - m_covered) + " of its " + std::to_string(end) +
                " samples are in no chunk and no gap (a chunk is missing)");
}

}  // namespace tactiscope::core::storage
