// SessionLayout: a station's store's rows fed to SessionBounds.
#include "core/storage/SessionLayout.h"

#include <limits>

namespace tactiscope::core::storage {

void SessionLayout::check(std::int64_t session)
{
    // Its duration: to its stop, or to now while it is being recorded; an
    // interrupted one (no stop) to its last chunk.
    auto exists = m_db.prepare(
        "SELECT (julianday(coalesce(ended_utc, CASE status WHEN 'recording' THEN 'now' ELSE started_utc END)) - "
        "julianday(started_utc)) * 86400 FROM sessions WHERE id = ?");
    exists.bind(1, session);
    if (!exists.step()) return;
    const double duration_s = exists.isNull(0) ? 0.0 : exists.real(0);

    auto channels = m_db.prepare("SELECT count(*), min(sample_rate_hz), max(sample_rate_hz), (SELECT count(*) FROM "
                                 "sessions WHERE parent_id = ?1) FROM channels WHERE session_id = ?1");
    channels.bind(1, session);
    channels.step();
    // A session of several devices holds no samples of its own: its parts
    // do, and each is checked as a session when it is read.
    if (channels.int64(0) == 0 && channels.int64(3) > 0) return;
    SessionBounds& bounds = m_checked.try_emplace(session, m_db.path(), session).first->second;
    bounds.session(duration_s, channels.int64(0), channels.real(1), channels.real(2));

    // From the start, the chunks and gaps below index 0 too (one moved there
    // by hand is damage); then only those after the ones checked.
    auto chunks = m_db.prepare("SELECT first_index, count, length(samples), first_time_s FROM chunks "
                               "WHERE session_id = ? AND first_index >= ? ORDER BY first_index");
    chunks.bind(1, session)
        .bind(2, bounds.chunkEnd() > 0 ? bounds.chunkEnd() : std::numeric_limits<std::int64_t>::min());
    while (chunks.step()) bounds.chunk(chunks.int64(0), chunks.int64(1), chunks.int64(2), chunks.real(3));

    auto gaps = m_db.prepare("SELECT first_index, count FROM gaps WHERE session_id = ? AND first_index >= ? "
                             "ORDER BY first_index");
    gaps.bind(1, session).bind(2, bounds.gapsFrom() > 0 ? bounds.gapsFrom() : std::numeric_limits<std::int64_t>::min());
    while (gaps.step()) bounds.gap(gaps.int64(0), gaps.int64(1));
    bounds.whole();
}

}  // namespace tactiscope::core::storage
