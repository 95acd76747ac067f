// SessionLayout: a stored session's counts, indices and gaps checked against
// its own bounds before anything is sized by them.
#include "core/storage/SessionLayout.h"

#include <cmath>
#include <string>

namespace tactiscope::core::storage {
namespace {

[[noreturn]] void damaged(const Database& db, std::int64_t session, const std::string& what)
{
    throw StoreInputError(db.path() + ": the store is damaged: in session " + std::to_string(session) + ", " + what +
                          "; its samples cannot be read");
}

}  // namespace

void SessionLayout::check(std::int64_t session)
{
    // Its duration: to its stop, or to now while it is being recorded; an
    // interrupted one (no stop) to its last chunk.
    auto exists = m_db.prepare(
        "SELECT (julianday(coalesce(ended_utc, CASE status WHEN 'recording' THEN 'now' ELSE started_utc END)) - "
        "julianday(started_utc)) * 86400 FROM sessions WHERE id = ?");
    exists.bind(1, session);
    if (!exists.step()) return;
    const double duration_s = exists.isNull(0) ? 0.0 : std::max(0.0, exists.real(0));

    auto channels = m_db.prepare("SELECT count(*), min(sample_rate_hz), max(sample_rate_hz) FROM channels "
                                 "WHERE session_id = ?");
    channels.bind(1, session);
    channels.step();
    const std::int64_t channelCount = channels.int64(0);
    if (channelCount == 0) damaged(m_db, session, "it has no channel rows");
    const double rate_hz = channels.real(2);
    if (!(std::isfinite(channels.real(1)) && channels.real(1) > 0.0 && std::isfinite(rate_hz)))
        damaged(m_db, session, "a channel's sample rate is not a positive number");

    Checked& done = m_checked[session];
    // Lost samples between two chunks: at most what the time between them
    // holds at the session's rate, twice over, plus two seconds of it.
    const auto mostLost = [&](double seconds) { return 2.0 * std::max(0.0, seconds) * rate_hz + 2.0 * rate_hz; };

    auto chunks = m_db.prepare("SELECT first_index, count, length(samples), first_time_s FROM chunks "
                               "WHERE session_id = ? AND first_index >= ? ORDER BY first_index");
    chunks.bind(1, session).bind(2, done.chunkEnd);
    while (chunks.step()) {
        const std::int64_t first = chunks.int64(0), count = chunks.int64(1), bytes = chunks.int64(2);
        const double time_s = chunks.real(3);
        const std::string which = "the chunk at sample " + std::to_string(first);
        if (first < 0) damaged(m_db, session, "a chunk starts at sample " + std::to_string(first));
        if (count < 1 || count > kMostChunkSamples)
            damaged(m_db, session, which + " says it holds " + std::to_string(count) + " samples");
        if (bytes != count * channelCount * 4)
            damaged(m_db, session,
                    which + " says it holds " + std::to_string(count) + " samples but has " + std::to_string(bytes) +
                        " bytes");
        if (!std::isfinite(time_s)) damaged(m_db, session, which + " has no time");
        if (done.chunks == 0) done.firstTime_s = time_s;
        if (first < done.chunkEnd) damaged(m_db, session, which + " overlaps the one before");
        // (The first chunk's samples before it: what its time from the
        // session's start allows.)
        const double allowed = done.chunks > 0 ? mostLost(time_s - done.chunkEndTime_s) : mostLost(time_s);
        if (static_cast<double>(first - done.chunkEnd) > allowed)
            damaged(m_db, session,
                    which + " comes " + std::to_string(first - done.chunkEnd) +
                        " samples after the one before it, more than its time allows");
        done.chunkEnd = first + count;
        done.chunkEndTime_s = time_s + static_cast<double>(count) / rate_hz;
        ++done.chunks;
    }

    // A gap runs at most to the session's end: the last chunk plus what its
    // duration from start to stop leaves (a probe lost before the stop).
    const double mostEnd =
        static_cast<double>(done.chunkEnd) + mostLost(duration_s - (done.chunkEndTime_s - done.firstTime_s));
    auto gaps = m_db.prepare("SELECT first_index, count FROM gaps WHERE session_id = ? AND first_index >= ? "
                             "ORDER BY first_index");
    gaps.bind(1, session).bind(2, done.gapsFrom);
    while (gaps.step()) {
        const std::int64_t first = gaps.int64(0), count = gaps.int64(1);
        if (first < 0 || count < 1)
            damaged(m_db, session,
                    "a gap at sample " + std::to_string(first) + " of " + std::to_string(count) + " samples");
        if (static_cast<double>(first) + static_cast<double>(count) > mostEnd)
            damaged(m_db, session,
                    "a gap of " + std::to_string(count) + " samples at sample " + std::to_string(first) +
                        " runs past the session's end");
        done.gapsFrom = first + 1;
    }
}

}  // namespace tactiscope::core::storage
