// CentralStore: the SQL that reads a central store as a SessionSource.
#include "core/storage/central/CentralStore.h"

#include "core/storage/ChunkCodec.h"
#include "core/storage/SessionBounds.h"
#include "core/storage/central/CentralSchema.h"
#include "core/text/UtcTime.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>
#include <thread>

namespace tactiscope::core::storage::central {
namespace {

// Chunks and the pyramid are kept by the month of their session's start
// (CentralSchema): a question naming it reads that month's table alone,
// where one without would look in every month's.
const std::string kInItsMonth = " AND session_month = (SELECT session_month(started_utc) FROM sessions WHERE id = $1)";

// A session's sample count: the end of its last chunk or last gap,
// whichever ends later (index lookups on both primary keys).
const std::string kSampleEnd =
    "greatest(coalesce((SELECT first_index + count FROM chunks WHERE session_id = s.id "
    "AND session_month = session_month(s.started_utc) ORDER BY first_index DESC "
    "LIMIT 1), 0), coalesce((SELECT first_index + count FROM gaps WHERE session_id = s.id ORDER BY first_index DESC "
    "LIMIT 1), 0))";

// Only complete uploads: a session a sync is still sending is not there.
// Its counts are the ones the server kept in its row as it was made
// complete (CentralSchema, listed_counts), asked of its rows only where
// none was kept (a row the owner wrote).
const std::string kSummaryQuery =
    "SELECT id, uuid, mode, subject, operator, site, notes, device_model, device_serial, device_firmware, "
    "profile_json, calibrations_json, started_utc, coalesce(ended_utc, ''), status, verdict, app_version, "
    "coalesce(listed_rate_hz, (SELECT sample_rate_hz FROM channels WHERE session_id = s.id AND position = 0), 0), "
    "coalesce(listed_samples, " +
    kSampleEnd +
    // A session of several devices counts its parts' events.
    "), coalesce(listed_events, (SELECT count(*) FROM events WHERE session_id = s.id AND analysis = 'live') + "
    "(SELECT count(*) FROM events e JOIN sessions p ON e.session_id = p.id WHERE p.parent_id = s.id AND "
    "e.analysis = 'live')), station, station_id, trigger_setup, coalesce(parent_id, 0), device_name, "
    "coalesce(listed_parts, (SELECT count(*) FROM sessions p WHERE p.parent_id = s.id AND p.complete)), unjudged, "
    "signal_setup " +
    "FROM sessions s WHERE complete ";

SessionSummary summaryFrom(const PgResult& r, int row)
{
    SessionSummary s;
    s.id = r.int64(row, 0);
    s.uuid = r.text(row, 1);
    // The schema's CHECKs admit only the vocabulary's modes and statuses.
    s.metadata = {modeFromString(r.text(row, 2)).value_or(Mode::General),  // a newer program's mode: as it came
                  r.text(row, 3),
                  r.text(row, 4),
                  r.text(row, 5),
                  r.text(row, 6),
                  r.text(row, 7),
                  r.text(row, 8),
                  r.text(row, 9),
                  r.text(row, 10),
                  r.text(row, 11),
                  r.text(row, 22),
                  r.int64(row, 23),
                  r.text(row, 24)};
    s.startedUtc = r.text(row, 12);
    s.endedUtc = r.text(row, 13);
    s.status = sessionStatusFromString(r.text(row, 14)).value_or(SessionStatus::Interrupted);
    s.verdict = verdictFromString(r.text(row, 15));
    s.appVersion = r.text(row, 16);
    s.sampleRate_hz = r.real(row, 17);
    s.sampleCount = static_cast<std::uint64_t>(r.int64(row, 18));
    s.eventCount = static_cast<std::uint64_t>(r.int64(row, 19));
    s.station = r.text(row, 20);
    s.stationId = r.int64(row, 21);
    s.devices = static_cast<std::size_t>(r.int64(row, 25));
    s.unjudged = r.text(row, 26);
    s.metadata.signalSetup = r.text(row, 27);
    return s;
}

// Every row of a result, each read by `read(result, row)`.
template <typename Read>
auto rowsOf(const PgResult& result, Read read)
{
    std::vector<decltype(read(result, 0))> rows;
    rows.reserve(static_cast<std::size_t>(result.rows()));
    for (int i = 0; i < result.rows(); ++i) rows.push_back(read(result, i));
    return rows;
}

std::string noChannel(std::int64_t session, std::size_t channel)
{
    return "session " + std::to_string(session) + " has no channel " + std::to_string(channel);
}

// The pyramid's rows in the central store's table `lod`.
class CentralLodRows : public lod::LodRows {
public:
    CentralLodRows(PgConnection& connection, std::int64_t session, std::size_t channel)
        : m_connection(connection),
          m_session(session),
          m_channel(static_cast<std::int64_t>(channel))
    {
    }

    std::uint64_t storedBuckets(int level) override
    {
        const PgResult r = m_connection.query(
            "SELECT first_bucket + count FROM lod WHERE session_id = $1 AND channel = $2 AND level = $3" + kInItsMonth +
                " ORDER BY first_bucket DESC LIMIT 1",
            PgParams().int64(m_session).int64(m_channel).int64(level), PgFormat::Binary);
        return r.rows() > 0 ? static_cast<std::uint64_t>(r.int64(0, 0)) : 0;
    }

    void read(int level, std::uint64_t firstBucket, std::uint64_t endBucket, lod::LodRowMap& rows) override
    {
        const PgResult r = m_connection.query(
            "SELECT first_bucket, count, buckets FROM lod WHERE session_id = $1 AND channel = $2 AND level = $3" +
                kInItsMonth + " AND first_bucket >= $4 AND first_bucket < $5",
            PgParams()
                .int64(m_session)
                .int64(m_channel)
                .int64(level)
                .int64(static_cast<std::int64_t>(firstBucket))
                .int64(static_cast<std::int64_t>(endBucket)),
            PgFormat::Binary);
        for (int i = 0; i < r.rows(); ++i)
            rows[{level, static_cast<std::uint64_t>(r.int64(i, 0))}] =
                lod::decodeBuckets(r.bytes(i, 2), static_cast<std::size_t>(r.int64(i, 1)));
    }

private:
    PgConnection& m_connection;
    std::int64_t m_session;
    std::int64_t m_channel;
};

// What the login may do, from the server's grants and role memberships
// (docs/fleet.md, "Roles and rights"); the owner and superusers may all.
// Column grants (which the roles have) do not count as a table's.
SessionSource::Rights rightsOf(PgConnection& connection, Database::Access access)
{
    if (access == Database::Access::ReadOnly) {
        const std::string why = "the central store is open read-only";
        return {why, why, why, why};
    }
    const PgResult r = connection.query(
        "SELECT has_table_privilege('sessions', 'DELETE'), pg_has_role('tactiscope_reviewer', 'MEMBER'), "
        "has_any_column_privilege('annotations', 'INSERT'), has_table_privilege('events', 'INSERT')");
    const auto yes = [&r](int column) { return r.text(0, column) == "t"; };
    const std::string login = connection.user();
    SessionSource::Rights rights;
    if (!yes(0)) rights.noDelete = "the login " + login + " may not delete sessions: only the store's owner does";
    if (!yes(1))
        rights.noReviewerVerdict =
            "the login " + login + " is not a reviewer's: a station adds only automatic and operator decisions";
    if (!yes(2)) rights.noNotes = "the login " + login + " may not add notes";
    if (!yes(3))
        rights.noAnalyses = "the login " + login +
                            " may not save analyses on the central store; export the session "
                            "or save it at a station";
    return rights;
}

}  // namespace

CentralStore::CentralStore(const std::string& conninfo, Database::Access access)
    : m_connection(conninfo)
{
    const PgResult schema = m_connection.query("SELECT to_regclass('schema_version') IS NOT NULL");
    if (schema.text(0, 0) != "t")
        throw StorageError(m_connection.location() +
                           " holds no Tactiscope store; its owner makes one with `tactiscope-cli server init`");
    const PgResult version = m_connection.query("SELECT max(version) FROM schema_version");
    if (version.isNull(0, 0) || version.int64(0, 0) > kCentralSchemaVersion)
        throw StorageError(m_connection.location() + " holds a central store of a newer Tactiscope (schema " +
                           version.text(0, 0) + "); update this program");
    if (version.int64(0, 0) < kCentralSchemaVersion)
        throw StorageError(m_connection.location() + " holds a central store of an older Tactiscope (schema " +
                           version.text(0, 0) + ", this program writes " + std::to_string(kCentralSchemaVersion) +
                           "); its owner updates it with `tactiscope-cli server init`");
    if (access == Database::Access::ReadOnly)
        m_connection.runOnEveryConnection("SET default_transaction_read_only = on");
    m_rights = rightsOf(m_connection, access);
    // A hot standby (a read replica) takes no write: those go to the primary
    // its address names beside it, when it names one.
    if (access == Database::Access::ReadWrite && m_connection.query("SELECT pg_is_in_recovery()").text(0, 0) == "t") {
        try {
            m_primary = std::make_unique<PgConnection>(conninfo, PgTarget::Primary);
        } catch (const StorageError& e) {
            // libpq's own words, without ours around them (it reached the replica).
            std::string why = e.what();
            if (const auto colon = why.find("cannot reach the central store: "); colon == 0)
                why.erase(0, std::string("cannot reach the central store: ").size());
            m_noPrimary = location() +
                          " is a read-only replica of the central store, and its address names no server that "
                          "takes writes (" +
                          why +
                          "): a verdict or a note is written on the primary. Name it after the replica in the "
                          "address, e.g. host=replica.site,db.site dbname=tactiscope "
                          "target_session_attrs=prefer-standby (reviews still read the replica)";
            m_rights = {m_noPrimary, m_noPrimary, m_noPrimary, m_noPrimary};
        }
    }
}

bool CentralStore::isReplica() const
{
    return m_primary || !m_noPrimary.empty();
}

PgConnection& CentralStore::writer()
{
    if (m_primary) return *m_primary;
    if (!m_noPrimary.empty()) throw StorageError(m_noPrimary);
    return m_connection;
}

void CentralStore::caughtUp()
{
    if (!m_primary) return;
    // What was just written on the primary is read from the replica once it
    // has replayed that far: a few milliseconds on a site's network; at
    // most 5 s waited, then read as it is.
    const std::string written = m_primary->query("SELECT pg_current_wal_lsn()::text").text(0, 0);
    for (int wait = 0; wait < 250; ++wait) {
        if (m_connection.query("SELECT coalesce(pg_last_wal_replay_lsn() >= $1::pg_lsn, true)", {written}).text(0, 0) ==
            "t")
            return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

CentralStore::Listing CentralStore::listing(const SessionFilter& filter)
{
    Listing listing;
    std::string where;
    int n = 0;
    const auto condition = [&](const std::string& value, const std::string& sql) {
        if (value.empty()) return;
        where += " AND " + sql + " $" + std::to_string(++n);
        listing.values.text(value);
    };
    condition(filter.startedFrom, "started_utc >=");
    condition(filter.startedBefore, "started_utc <");
    if (filter.mode) condition(std::string(toString(*filter.mode)), "mode =");
    condition(filter.subject, "subject =");
    condition(filter.operatorName, "operator =");
    if (filter.verdict) condition(std::string(toString(*filter.verdict)), "verdict =");
    if (filter.status) condition(std::string(toString(*filter.status)), "status =");
    condition(filter.station, "station =");
    if (!filter.text.empty()) {
        // Through the trigram index, as the owner, whatever the login may
        // not see left out (CentralSchema: sessions_with_text); ILIKE as
        // SQLite's LIKE ignores case.
        where += " AND id IN (SELECT sessions_with_text($" + std::to_string(++n) + "))";
        listing.values.text(textSearchPattern(filter.text));
    }
    if (filter.after) {
        where +=
            " AND (started_utc, id) < (SELECT started_utc, id FROM sessions WHERE id = $" + std::to_string(++n) + ")";
        listing.values.int64(*filter.after);
    }
    // LIMIT NULL: all of them.
    filter.limit > 0 ? listing.values.int64(static_cast<std::int64_t>(filter.limit)) : listing.values.null();
    // A device's part is listed with its session, not of its own.
    listing.sql = kSummaryQuery + "AND parent_id IS NULL" + where + " ORDER BY started_utc DESC, id DESC LIMIT $" +
                  std::to_string(++n) + "::bigint";
    return listing;
}

std::vector<SessionSummary> CentralStore::sessions(const SessionFilter& filter)
{
    const Listing query = listing(filter);
    const PgResult r = m_connection.query(query.sql, query.values, PgFormat::Binary);
    auto summaries = rowsOf(r, [](const PgResult& q, int i) { return summaryFrom(q, i); });
    for (SessionSummary& summary : summaries) fillFromLongestPart(summary);
    return summaries;
}

std::string CentralStore::listingPlan(const SessionFilter& filter)
{
    const Listing query = listing(filter);
    return m_connection.query("EXPLAIN (FORMAT JSON) " + query.sql, query.values).text(0, 0);
}

std::optional<SessionSummary> CentralStore::session(std::int64_t id)
{
    const PgResult r = m_connection.query(kSummaryQuery + "AND id = $1", PgParams().int64(id), PgFormat::Binary);
    if (r.rows() == 0) return std::nullopt;
    SessionSummary summary = summaryFrom(r, 0);
    fillFromLongestPart(summary);
    return summary;
}

std::vector<SessionPart> CentralStore::parts(std::int64_t session)
{
    const PgResult r = m_connection.query(
        "SELECT id, device_name, device_model, device_serial, device_firmware, clock_json, status FROM sessions "
        "WHERE complete AND parent_id = $1 ORDER BY id",
        PgParams().int64(session), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return SessionPart{q.int64(i, 0),
                           q.text(i, 1),
                           q.text(i, 2),
                           q.text(i, 3),
                           q.text(i, 4),
                           q.text(i, 5),
                           sessionStatusFromString(q.text(i, 6)).value_or(SessionStatus::Interrupted)};
    });
}

std::optional<std::int64_t> CentralStore::sessionWithUuid(const std::string& uuid)
{
    const PgResult r = m_connection.query("SELECT id FROM sessions WHERE complete AND uuid = $1", {uuid});
    if (r.rows() == 0) return std::nullopt;
    return r.int64(0, 0);
}

std::optional<std::int64_t> CentralStore::lastSession()
{
    // The primary key walked from its end: the first this login may see
    // (row-level security) that is whole and no part.
    const PgResult r =
        m_connection.query("SELECT id FROM sessions WHERE complete AND parent_id IS NULL ORDER BY id DESC LIMIT 1",
                           PgParams(), PgFormat::Binary);
    if (r.rows() == 0) return std::nullopt;
    return r.int64(0, 0);
}

std::vector<std::string> CentralStore::stations()
{
    // Each name the next one after the last through the station index: a
    // few dozen index probes, where DISTINCT would read every session.
    const PgResult r = m_connection.query(
        "WITH RECURSIVE named(station) AS ("
        " (SELECT station FROM sessions WHERE complete AND parent_id IS NULL ORDER BY station LIMIT 1)"
        " UNION ALL SELECT (SELECT s.station FROM sessions s WHERE s.complete AND s.parent_id IS NULL"
        " AND s.station > named.station ORDER BY s.station LIMIT 1) FROM named WHERE named.station IS NOT NULL)"
        " SELECT station FROM named WHERE station IS NOT NULL");
    return rowsOf(r, [](const PgResult& q, int i) { return q.text(i, 0); });
}

void CentralStore::checkLayout(std::int64_t session)
{
    if (m_checked.contains(session)) return;
    const PgResult s = m_connection.query(
        "SELECT started_utc, coalesce(ended_utc, ''), (SELECT count(*) FROM channels WHERE session_id = s.id), "
        "(SELECT min(sample_rate_hz) FROM channels WHERE session_id = s.id), "
        "(SELECT max(sample_rate_hz) FROM channels WHERE session_id = s.id), "
        "(SELECT count(*) FROM sessions p WHERE p.parent_id = s.id), "
        "(SELECT detached_utc FROM detached_months WHERE month = session_month(s.started_utc)) "
        "FROM sessions s WHERE complete AND id = $1",
        PgParams().int64(session), PgFormat::Binary);
    if (s.rows() == 0) return;  // not listed: nothing of it is read
    // Its month's samples taken out of the store by its owner (server
    // maintain --detach-before), to be archived: its fields, records and
    // verdict trail read as ever, its samples say where they went.
    if (!s.isNull(0, 6)) {
        m_detached[session] = location() + ": the samples of session " + std::to_string(session) +
                              " are not in the central store: the month it started in (" + s.text(0, 0).substr(0, 7) +
                              ") was detached on " + s.text(0, 6) +
                              " to be archived; its owner attaches it again with tactiscope-cli server maintain "
                              "--attach " +
                              s.text(0, 0).substr(0, 7);
        m_checked.insert(session);
        return;
    }
    // A session of several devices holds no samples of its own: its parts
    // do, and each is checked as a session when it is read.
    if (s.int64(0, 2) == 0 && s.int64(0, 5) > 0) {
        m_checked.insert(session);
        return;
    }
    const auto started = text::utcSeconds(s.text(0, 0)), ended = text::utcSeconds(s.text(0, 1));
    SessionBounds bounds(location(), session);
    bounds.session(started && ended ? *ended - *started : 0.0, s.int64(0, 2), s.isNull(0, 3) ? 0.0 : s.real(0, 3),
                   s.isNull(0, 4) ? 0.0 : s.real(0, 4));
    const PgResult chunks = m_connection.query(
        "SELECT first_index, count, octet_length(samples), first_time_s FROM chunks WHERE session_id = $1" +
            kInItsMonth + " ORDER BY first_index",
        PgParams().int64(session), PgFormat::Binary);
    for (int i = 0; i < chunks.rows(); ++i)
        bounds.chunk(chunks.int64(i, 0), chunks.int64(i, 1), chunks.int64(i, 2), chunks.real(i, 3));
    const PgResult gaps =
        m_connection.query("SELECT first_index, count FROM gaps WHERE session_id = $1 ORDER BY first_index",
                           PgParams().int64(session), PgFormat::Binary);
    for (int i = 0; i < gaps.rows(); ++i) bounds.gap(gaps.int64(i, 0), gaps.int64(i, 1));
    bounds.whole();
    m_checked.insert(session);
}

std::vector<StoredChannel> CentralStore::channels(std::int64_t session)
{
    checkLayout(session);
    const PgResult r = m_connection.query(
        "SELECT name, unit, kind, sample_rate_hz, role FROM channels WHERE session_id = $1 ORDER BY position",
        PgParams().int64(session), PgFormat::Binary);
    std::vector<StoredChannel> result;
    for (int i = 0; i < r.rows(); ++i) {
        const auto kind = channelKindFromString(r.text(i, 2)).value_or(ChannelKind::Other);
        result.push_back({{r.text(i, 0), r.text(i, 1), kind, channelRoleFromString(r.text(i, 4))}, r.real(i, 3)});
    }
    return result;
}

void CentralStore::refuseIfDetached(std::int64_t session)
{
    checkLayout(session);
    if (const auto detached = m_detached.find(session); detached != m_detached.end())
        throw StoreInputError(detached->second);
}

std::uint64_t CentralStore::sampleCount(std::int64_t session)
{
    checkLayout(session);
    // The count kept as it was made complete: a detached month's session
    // still has one.
    const PgResult r =
        m_connection.query("SELECT coalesce(listed_samples, " + kSampleEnd + ") FROM sessions s WHERE id = $1",
                           PgParams().int64(session), PgFormat::Binary);
    return static_cast<std::uint64_t>(r.int64(0, 0));
}

std::vector<SampleGap> CentralStore::gaps(std::int64_t session)
{
    checkLayout(session);
    const PgResult r =
        m_connection.query("SELECT first_index, count FROM gaps WHERE session_id = $1 ORDER BY first_index",
                           PgParams().int64(session), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return SampleGap{static_cast<std::uint64_t>(q.int64(i, 0)), static_cast<std::uint64_t>(q.int64(i, 1))};
    });
}

std::size_t CentralStore::readChannels(std::int64_t session, std::span<const std::size_t> channels,
                                       std::uint64_t firstIndex, std::uint64_t count,
                                       std::vector<std::vector<double>>& out)
{
    const std::size_t channelCount = this->channels(session).size();
    for (const std::size_t channel : channels)
        if (channel >= channelCount) throw StorageError(noChannel(session, channel));
    const std::uint64_t end = std::min(sampleCount(session), firstIndex + count);
    const std::size_t n = firstIndex < end ? static_cast<std::size_t>(end - firstIndex) : 0;
    if (n > kMostSamplesPerRead)
        throw StorageError("session " + std::to_string(session) + " would need " + std::to_string(n) +
                           " samples read at once, more than a computer holds");
    refuseIfDetached(session);
    out.resize(channels.size());
    // NaN first: whatever no chunk covers is a gap.
    for (auto& samples : out) samples.assign(n, std::numeric_limits<double>::quiet_NaN());
    if (n == 0) return 0;
    // From the chunk holding firstIndex (it starts at or before it).
    const PgResult r = m_connection.query(
        "SELECT first_index, count, samples FROM chunks WHERE session_id = $1" + kInItsMonth +
            " AND first_index >= coalesce((SELECT max(first_index) FROM chunks WHERE session_id = $1" + kInItsMonth +
            " AND first_index <= $2), 0) "
            "AND first_index < $3 ORDER BY first_index",
        PgParams().int64(session).int64(static_cast<std::int64_t>(firstIndex)).int64(static_cast<std::int64_t>(end)),
        PgFormat::Binary);
    for (int i = 0; i < r.rows(); ++i) {
        const auto chunkFirst = static_cast<std::uint64_t>(r.int64(i, 0));
        const auto chunkCount = static_cast<std::uint64_t>(r.int64(i, 1));
        const auto blob = r.bytes(i, 2);  // its size checked with the layout
        const std::uint64_t begin = std::max(chunkFirst, firstIndex);
        const std::uint64_t stop = std::min(chunkFirst + chunkCount, end);
        if (stop <= begin) continue;
        for (std::size_t k = 0; k < channels.size(); ++k)
            decodeChunkChannel(blob, channelCount, chunkCount, channels[k], begin - chunkFirst,
                               std::span(out[k]).subspan(begin - firstIndex, stop - begin));
        ++m_chunksRead;
    }
    return n;
}

std::vector<OverviewPoint> CentralStore::overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                                  std::uint64_t count, std::size_t points)
{
    if (channel >= channels(session).size()) throw StorageError(noChannel(session, channel));
    const std::uint64_t end = std::min(sampleCount(session), firstIndex + count);
    if (firstIndex >= end) return {};
    refuseIfDetached(session);
    lod::LodTable pyramid(std::make_unique<CentralLodRows>(m_connection, session, channel), session,
                          [this, session, channel](std::uint64_t first, std::uint64_t n) {
                              return readChannel(session, channel, first, n);
                          });
    return pyramid.overview(firstIndex, end, points);
}

std::vector<SessionEvent> CentralStore::events(std::int64_t session, const std::string& analysis)
{
    const PgResult r = m_connection.query(
        "SELECT id, analysis, kind, start_s, end_s, direction, peak_r, lag_s, speed_m_per_s, note FROM events "
        "WHERE session_id = $1 AND analysis = $2 ORDER BY start_s, id",
        PgParams().int64(session).text(analysis), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return SessionEvent{
            q.int64(i, 0),        q.text(i, 1),         eventKindFromString(q.text(i, 2)).value_or(EventKind::Marker),
            q.real(i, 3),         q.real(i, 4),         static_cast<int>(q.int64(i, 5)),
            q.optionalReal(i, 6), q.optionalReal(i, 7), q.optionalReal(i, 8),
            q.text(i, 9)};
    });
}

std::vector<std::string> CentralStore::analyses(std::int64_t session)
{
    const PgResult r = m_connection.query(
        "SELECT analysis COLLATE \"C\" AS name FROM events WHERE session_id = $1 AND analysis <> $2 UNION "
        "SELECT analysis COLLATE \"C\" FROM readings WHERE session_id = $1 AND analysis <> $2 ORDER BY name",
        PgParams().int64(session).text(kLiveAnalysis));
    std::vector<std::string> result{kLiveAnalysis};
    for (int i = 0; i < r.rows(); ++i) result.push_back(r.text(i, 0));
    return result;
}

std::vector<SessionReading> CentralStore::readings(std::int64_t session, const std::string& analysis)
{
    const PgResult r = m_connection.query(
        "SELECT id, kind, start_s, end_s, quantity, value, unit, standard_error, site, details_json, analysis "
        "FROM readings WHERE session_id = $1 AND analysis = $2 ORDER BY start_s, id",
        PgParams().int64(session).text(analysis), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return SessionReading{q.int64(i, 0), readingKindFromString(q.text(i, 1)).value_or(ReadingKind::Compliance),
                              q.real(i, 2),  q.real(i, 3),
                              q.text(i, 4),  q.real(i, 5),
                              q.text(i, 6),  q.optionalReal(i, 7),
                              q.text(i, 8),  q.text(i, 9),
                              q.text(i, 10)};
    });
}

std::vector<Annotation> CentralStore::annotations(std::int64_t session)
{
    const PgResult r = m_connection.query(
        "SELECT id, time_s, author, text, created_utc, modified_utc FROM annotations WHERE session_id = $1 "
        "ORDER BY time_s, id",
        PgParams().int64(session), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return Annotation{q.int64(i, 0), q.real(i, 1), q.text(i, 2), q.text(i, 3), q.text(i, 4), q.text(i, 5)};
    });
}

std::vector<VerdictDecision> CentralStore::verdicts(std::int64_t session)
{
    const PgResult r = m_connection.query(
        "SELECT id, role, verdict, decided_by, decided_utc, note, basis_json FROM verdicts WHERE session_id = $1 "
        "ORDER BY id",
        PgParams().int64(session), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return VerdictDecision{q.int64(i, 0),
                               verdictRoleFromString(q.text(i, 1)).value_or(VerdictRole::Reviewer),
                               verdictFromString(q.text(i, 2)).value_or(Verdict::DefectsFound),
                               q.text(i, 3),
                               q.text(i, 4),
                               q.text(i, 5),
                               q.text(i, 6)};
    });
}

std::vector<SessionZero> CentralStore::zeros(std::int64_t session)
{
    const PgResult r =
        m_connection.query("SELECT first_index, values_json FROM zeros WHERE session_id = $1 ORDER BY first_index",
                           PgParams().int64(session), PgFormat::Binary);
    return rowsOf(r, [](const PgResult& q, int i) {
        return SessionZero{static_cast<std::uint64_t>(q.int64(i, 0)), q.text(i, 1)};
    });
}

namespace {

std::vector<StoredCalibration> calibrationsFrom(const PgResult& r)
{
    std::vector<StoredCalibration> result;
    for (int i = 0; i < r.rows(); ++i) {
        try {
            result.push_back({r.int64(i, 0), calibration::CalibrationRecord::fromJson(r.text(i, 1))});
        } catch (const std::invalid_argument& e) {
            throw StorageError("calibration " + r.text(i, 0) + " cannot be read (" + e.what() +
                               "); the central store is damaged");
        }
    }
    return result;
}

}  // namespace

std::optional<StoredCalibration> CentralStore::calibration(std::int64_t id)
{
    auto found = calibrationsFrom(
        m_connection.query("SELECT id, record_json FROM calibrations WHERE id = $1", PgParams().int64(id)));
    if (found.empty()) return std::nullopt;
    return std::move(found.front());
}

std::vector<StoredCalibration> CentralStore::calibrations(const std::string& sensor)
{
    return calibrationsFrom(m_connection.query(
        "SELECT id, record_json FROM calibrations WHERE $1 = '' OR sensor = $1 ORDER BY created_utc, id", {sensor}));
}

std::int64_t CentralStore::addCalibration(const calibration::CalibrationRecord& r)
{
    const std::int64_t id =
        writer()
            .query("INSERT INTO calibrations (kind, sensor, operator, created_utc, r_squared, points, record_json) "
                   "VALUES ($1, $2, $3, $4, $5, $6, $7) RETURNING id",
                   PgParams()
                       .text(r.kind)
                       .text(r.sensorName)
                       .text(r.operatorName)
                       .text(r.timestampUtc)
                       .real(r.fit.rSquared)
                       .int64(static_cast<std::int64_t>(r.fit.points))
                       .text(r.toJson()))
            .int64(0, 0);
    caughtUp();
    return id;
}

std::vector<std::int64_t> CentralStore::ids(const std::string& sql, std::int64_t parameter)
{
    const PgResult r = m_connection.query(sql, PgParams().int64(parameter));
    return rowsOf(r, [](const PgResult& q, int i) { return q.int64(i, 0); });
}

std::vector<std::int64_t> CentralStore::calibrationsOfSession(std::int64_t session)
{
    return ids("SELECT calibration_id FROM session_calibrations WHERE session_id = $1 ORDER BY calibration_id",
               session);
}

std::vector<std::int64_t> CentralStore::sessionsUsingCalibration(std::int64_t calibration)
{
    return ids("SELECT session_id FROM session_calibrations WHERE calibration_id = $1 ORDER BY session_id",
               calibration);
}

std::int64_t CentralStore::decideVerdict(std::int64_t session, const VerdictDecision& d)
{
    // The server sets the session's verdict from its trail: a decision is
    // one row of it, on a finished session this role may see.
    PgTransaction transaction(writer());
    const PgResult visible =
        writer().query("SELECT id FROM sessions WHERE id = $1 AND complete", PgParams().int64(session));
    if (visible.rows() == 0)
        throw StorageError("session " + std::to_string(session) + " is not in the central store, or this role (" +
                           m_connection.user() + ") may not decide its verdict");
    const std::int64_t id = addToVerdictTrail(session, d);
    transaction.commit();
    caughtUp();
    return id;
}

std::int64_t CentralStore::addToVerdictTrail(std::int64_t session, const VerdictDecision& d)
{
    return writer()
        .query("INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc, note, basis_json) "
               "VALUES ($1, $2, $3, $4, $5, $6, $7) RETURNING id",
               PgParams()
                   .int64(session)
                   .text(std::string(toString(d.role)))
                   .text(std::string(toString(d.verdict)))
                   .text(d.decidedBy)
                   .text(d.decidedUtc.empty() ? text::utcNow() : d.decidedUtc)
                   .text(d.note)
                   .text(d.basisJson))
        .int64(0, 0);
}

void CentralStore::addZero(std::int64_t session, const SessionZero& zero)
{
    writer().query("INSERT INTO zeros (session_id, first_index, values_json) VALUES ($1, $2, $3)",
                   PgParams().int64(session).int64(static_cast<std::int64_t>(zero.firstIndex)).text(zero.valuesJson));
}

std::int64_t CentralStore::addAnnotation(std::int64_t session, const Annotation& a)
{
    const std::string now = text::utcNow();
    const std::int64_t id =
        writer()
            .query("INSERT INTO annotations (session_id, time_s, author, text, created_utc, modified_utc) "
                   "VALUES ($1, $2, $3, $4, $5, $6) RETURNING id",
                   PgParams()
                       .int64(session)
                       .real(a.time_s)
                       .text(a.author)
                       .text(a.text)
                       .text(a.createdUtc.empty() ? now : a.createdUtc)
                       .text(a.modifiedUtc.empty() ? now : a.modifiedUtc))
            .int64(0, 0);
    caughtUp();
    return id;
}

void CentralStore::updateAnnotation(std::int64_t annotation, const std::string& text)
{
    const PgResult r = writer().query("UPDATE annotations SET text = $1, modified_utc = $2 WHERE id = $3 RETURNING id",
                                      PgParams().text(text).text(text::utcNow()).int64(annotation));
    if (r.rows() == 0)
        throw StorageError("there is no annotation " + std::to_string(annotation) + " this role may change");
    caughtUp();
}

void CentralStore::deleteAnnotation(std::int64_t annotation)
{
    const PgResult r =
        writer().query("DELETE FROM annotations WHERE id = $1 RETURNING id", PgParams().int64(annotation));
    if (r.rows() == 0)
        throw StorageError("there is no annotation " + std::to_string(annotation) + " this role may delete");
    caughtUp();
}

void CentralStore::addEvents(std::int64_t session, std::span<const SessionEvent> events)
{
    PgTransaction transaction(writer());
    for (const SessionEvent& e : events)
        writer().query("INSERT INTO events (session_id, analysis, kind, start_s, end_s, direction, peak_r, lag_s, "
                       "speed_m_per_s, note) VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10)",
                       PgParams()
                           .int64(session)
                           .text(e.analysis)
                           .text(std::string(toString(e.kind)))
                           .real(e.start_s)
                           .real(e.end_s)
                           .int64(e.direction)
                           .optionalReal(e.peakR)
                           .optionalReal(e.lag_s)
                           .optionalReal(e.speed_m_per_s)
                           .text(e.note));
    transaction.commit();
    caughtUp();
}

void CentralStore::addReadings(std::int64_t session, std::span<const SessionReading> readings)
{
    PgTransaction transaction(writer());
    for (const SessionReading& r : readings)
        writer().query("INSERT INTO readings (session_id, kind, start_s, end_s, quantity, value, unit, "
                       "standard_error, site, details_json, analysis) "
                       "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11)",
                       PgParams()
                           .int64(session)
                           .text(std::string(toString(r.kind)))
                           .real(r.start_s)
                           .real(r.end_s)
                           .text(r.quantity)
                           .real(r.value)
                           .text(r.unit)
                           .optionalReal(r.standardError)
                           .text(r.site)
                           .text(r.detailsJson)
                           .text(r.analysis));
    transaction.commit();
    caughtUp();
}

void CentralStore::deleteSession(std::int64_t session)
{
    const auto summary = this->session(session);
    if (!summary) throw StorageError("there is no session " + std::to_string(session));
    if (const auto refusal = partDeletionRefusal(*summary)) throw StorageError(*refusal);
    // Only the owner has DELETE; the server refuses anyone else.
    const PgResult r = writer().query("DELETE FROM sessions WHERE id = $1 RETURNING id", PgParams().int64(session));
    if (r.rows() == 0)
        throw StorageError("session " + std::to_string(session) + " may not be deleted by " + m_connection.user());
    caughtUp();
}

}  // namespace tactiscope::core::storage::central
