// CentralSync: one station session copied to the central store per
// transaction; samples re-chunked (ServerChunks), pyramid rows as stored,
// bound as binary in multi-row INSERTs (COPY is not allowed under
// row-level security).
#include "core/storage/central/CentralSync.h"

#include "core/storage/central/ServerChunks.h"

#include "core/text/Md5.h"
#include "core/text/TextChecks.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <thread>

namespace tactiscope::core::storage::central {
namespace {

// One checksum line per chunk; the server builds the same from what
// arrived before it lets a session be complete (CentralSchema).
std::string chunkLine(std::uint64_t firstIndex, std::uint64_t count, std::span<const std::uint8_t> samples)
{
    return std::to_string(firstIndex) + ":" + std::to_string(count) + ":" + text::md5Hex(samples);
}

// Rows of one table sent a few hundred (or ~16 MB) at a time: one round
// trip per batch rather than per row.
class RowBatch {
public:
    RowBatch(PgConnection& db, std::string insert, int columns)
        : m_db(db),
          m_insert(std::move(insert)),
          m_columns(columns)
    {
    }

    // The parameters to add the next row's `columns` values to.
    PgParams& row()
    {
        constexpr int kRows = 256;
        constexpr std::size_t kBytes = std::size_t{16} << 20;
        if (m_rows >= kRows || m_params.bytesHeld() >= kBytes) flush();
        ++m_rows;
        return m_params;
    }

    void flush()
    {
        if (m_rows == 0) return;
        std::string sql = m_insert + " VALUES ";
        for (int r = 0, p = 0; r < m_rows; ++r) {
            sql += r ? ", (" : "(";
            for (int c = 0; c < m_columns; ++c) sql += (c ? ", $" : "$") + std::to_string(++p);
            sql += ")";
        }
        m_db.query(sql, m_params);
        m_params = PgParams();
        m_rows = 0;
    }

private:
    PgConnection& m_db;
    std::string m_insert;
    int m_columns;
    PgParams m_params;
    int m_rows = 0;
};

class SessionUpload {
public:
    SessionUpload(SessionStore& local, CentralStore& central, std::string station)
        : m_local(local),
          m_central(central),
          m_db(central.connection()),
          m_station(std::move(station))
    {
    }

    // Sends one session, and a session of several devices with all its
    // parts, whole or not at all; returns the values sent.
    std::uint64_t send(const SessionSummary& s, const std::string& checksum)
    {
        // The months its rows go in, made before its transaction (see
        // month_ready in CentralSchema).
        const std::vector<SessionPart> parts = m_local.parts(s.id);
        std::vector<SessionSummary> partSummaries;
        m_months.clear();
        if (s.devices == 0) m_months[s.id] = monthReady(s.startedUtc);
        for (const SessionPart& part : parts) {
            const auto summary = m_local.session(part.id);
            if (!summary) throw StorageError("its part " + std::to_string(part.id) + " cannot be read");
            m_months[part.id] = monthReady(summary->startedUtc);
            partSummaries.push_back(*summary);
        }
        PgTransaction transaction(m_db);
        std::uint64_t values = 0;
        if (s.devices == 0) {
            values = sendRows(s, checksum, {});
        } else {
            // The session itself holds no samples: its records, then each
            // device's part under it, then the session made complete.
            const std::int64_t id = insertSession(s, {});
            insertRecords(s.id, id);
            for (std::size_t p = 0; p < parts.size(); ++p)
                values +=
                    sendRows(partSummaries[p], sessionChecksum(m_local, parts[p].id), PartRow{id, parts[p].clockJson});
            m_db.query("UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2",
                       PgParams().text(checksum).int64(id));
        }
        transaction.commit();
        return values;
    }

    // Decisions and notes made at the station after the session was sent
    // (an operator's verdict comes once the recording has ended) join the
    // server's, which may hold a reviewer's too; the session's verdict is
    // then the latest decision's (the server derives it). Returns whether
    // anything was added.
    bool addLaterRecords(std::int64_t local, std::int64_t id)
    {
        PgTransaction transaction(m_db);
        bool added = false;
        const auto trail = m_central.verdicts(id);
        for (const VerdictDecision& d : m_local.verdicts(local)) {
            if (d.role == VerdictRole::Reviewer) continue;  // a station sends no reviewer decision
            const auto same = [&d](const VerdictDecision& t) {
                return t.role == d.role && t.verdict == d.verdict && t.decidedBy == d.decidedBy &&
                       t.decidedUtc == d.decidedUtc;
            };
            if (std::ranges::any_of(trail, same)) continue;
            m_central.addToVerdictTrail(id, d);
            added = true;
        }
        const auto notes = m_central.annotations(id);
        for (const Annotation& a : m_local.annotations(local)) {
            const auto same = [&a](const Annotation& n) {
                return n.createdUtc == a.createdUtc && n.author == a.author && n.time_s == a.time_s;
            };
            if (std::ranges::any_of(notes, same)) continue;
            m_central.addAnnotation(id, a);
            added = true;
        }
        transaction.commit();
        return added;
    }

private:
    // The month a session started at `startedUtc` is kept in, as the
    // server names it (its first day), its partitions made.
    std::string monthReady(const std::string& startedUtc)
    {
        return m_db.query("SELECT month_ready($1)", {startedUtc}).text(0, 0);
    }

    struct PartRow {
        std::int64_t parent = 0;  // the session's id on the server
        std::string clockJson;
    };

    // A session of one device, or one device's part: its row, samples,
    // pyramid and records, checked against what the station holds.
    std::uint64_t sendRows(const SessionSummary& s, const std::string& checksum, const std::optional<PartRow>& part)
    {
        const std::int64_t id = insertSession(s, part);
        insertChannelsAndGaps(s.id, id);  // first: the server checks each chunk against the channels
        const std::uint64_t values = copyChunks(s.id, id);
        copyPyramid(s.id, id);
        insertRecords(s.id, id);
        insertCalibrations(s.id, id);
        // The last step, which the server refuses unless what arrived is
        // what the station holds.
        m_db.query("UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2",
                   PgParams().text(checksum).int64(id));
        return values;
    }

    std::int64_t insertSession(const SessionSummary& s, const std::optional<PartRow>& part)
    {
        const SessionMetadata& m = s.metadata;
        PgParams p;
        p.text(s.uuid).text(m_station).text(std::string(toString(m.mode))).text(m.subject).text(m.operatorName);
        p.text(m.site).text(m.notes).text(s.startedUtc);
        s.endedUtc.empty() ? p.null() : p.text(s.endedUtc);
        // No verdict: the server derives it from the trail sent with it.
        p.text(std::string(toString(s.status)));
        p.text(m.deviceModel).text(m.deviceSerial).text(m.deviceFirmware).text(m.profileJson);
        p.text(m.calibrationsJson).text(s.appVersion).int64(s.id).text(m.trigger);
        part ? p.int64(part->parent) : p.null();
        p.text(m.deviceName).text(part ? part->clockJson : std::string{}).text(s.unjudged).text(m.signalSetup);
        return m_db
            .query(
                "INSERT INTO sessions (uuid, station, mode, subject, operator, site, notes, started_utc, ended_utc, "
                "status, device_model, device_serial, device_firmware, profile_json, calibrations_json, "
                "app_version, station_id, trigger_setup, parent_id, device_name, clock_json, unjudged, signal_setup) "
                "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16, $17, $18, $19, $20, "
                "$21, $22, $23) "
                "RETURNING id",
                p)
            .int64(0, 0);
    }

    std::uint64_t copyChunks(std::int64_t local, std::int64_t id)
    {
        RowBatch rows(m_db, "INSERT INTO chunks (session_id, session_month, first_index, first_time_s, count, samples)",
                      6);
        std::uint64_t values = 0;
        forEachServerChunk(m_local, local, [&](const SessionStore::RawChunk& c) {
            rows.row()
                .int64(id)
                .text(m_months.at(local))
                .int64(static_cast<std::int64_t>(c.firstIndex))
                .real(c.firstTime_s)
                .int64(static_cast<std::int64_t>(c.count))
                .bytes(c.samples);
            values += c.samples.size() / 4;
        });
        rows.flush();
        return values;
    }

    void insertChannelsAndGaps(std::int64_t local, std::int64_t id)
    {
        int position = 0;
        for (const StoredChannel& c : m_local.channels(local))
            m_db.query("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) "
                       "VALUES ($1, $2, $3, $4, $5, $6, $7)",
                       PgParams()
                           .int64(id)
                           .int64(position++)
                           .text(c.descriptor.name)
                           .text(c.descriptor.unit)
                           .text(std::string(toString(c.descriptor.kind)))
                           .real(c.sampleRate_hz)
                           .text(std::string(roleWord(c.descriptor.role))));
        for (const SampleGap& g : m_local.gaps(local))
            m_db.query("INSERT INTO gaps (session_id, first_index, count) VALUES ($1, $2, $3)",
                       PgParams()
                           .int64(id)
                           .int64(static_cast<std::int64_t>(g.firstIndex))
                           .int64(static_cast<std::int64_t>(g.count)));
    }

    void copyPyramid(std::int64_t local, std::int64_t id)
    {
        RowBatch rows(m_db, "INSERT INTO lod (session_id, session_month, channel, level, first_bucket, count, buckets)",
                      7);
        m_local.forEachLodRow(local, [&](const SessionStore::RawLodRow& r) {
            rows.row()
                .int64(id)
                .text(m_months.at(local))
                .int64(r.channel)
                .int64(r.level)
                .int64(static_cast<std::int64_t>(r.firstBucket))
                .int64(static_cast<std::int64_t>(r.count))
                .bytes(r.buckets);
        });
        rows.flush();
    }

    void insertRecords(std::int64_t local, std::int64_t id)
    {
        for (const std::string& analysis : m_local.analyses(local)) {
            m_central.addEvents(id, m_local.events(local, analysis));
            m_central.addReadings(id, m_local.readings(local, analysis));
        }
        for (const Annotation& a : m_local.annotations(local)) m_central.addAnnotation(id, a);
        for (const SessionZero& z : m_local.zeros(local)) m_central.addZero(id, z);
        for (const VerdictDecision& d : m_local.verdicts(local))
            if (d.role != VerdictRole::Reviewer) m_central.addToVerdictTrail(id, d);  // a station sends none
    }

    // The calibrations the session used, shared with the station's other
    // sessions: each sent once, found again by its identity.
    void insertCalibrations(std::int64_t local, std::int64_t id)
    {
        for (const std::int64_t c : m_local.calibrationsOfSession(local)) {
            const auto stored = m_local.calibration(c);
            if (!stored) continue;
            const calibration::CalibrationRecord& r = stored->record;
            const PgParams identity = PgParams().text(m_station).text(r.sensorName).text(r.timestampUtc).text(r.kind);
            PgParams insert = identity;
            insert.text(r.operatorName).real(r.fit.rSquared).int64(static_cast<std::int64_t>(r.fit.points));
            insert.text(r.toJson());
            m_db.query("INSERT INTO calibrations (station, sensor, created_utc, kind, operator, r_squared, points, "
                       "record_json) VALUES ($1, $2, $3, $4, $5, $6, $7, $8) ON CONFLICT DO NOTHING",
                       insert);
            const std::int64_t central =
                m_db.query("SELECT id FROM calibrations WHERE station = $1 AND sensor = $2 AND created_utc = $3 "
                           "AND kind = $4",
                           identity)
                    .int64(0, 0);
            m_db.query("INSERT INTO session_calibrations VALUES ($1, $2) ON CONFLICT DO NOTHING",
                       PgParams().int64(id).int64(central));
        }
    }

    SessionStore& m_local;
    CentralStore& m_central;
    PgConnection& m_db;
    std::string m_station;
    std::map<std::int64_t, std::string> m_months;  // of the session being sent and its parts, by local id
};

// What the server holds of a session this role may see.
struct OnServer {
    std::int64_t id = 0;
    std::string checksum;
};

// Each uuid is a parameter of its own, never spliced into a literal: a
// stored uuid holding '"' or '\\' once made the array literal malformed and
// stopped every later sync of the station.
std::map<std::string, OnServer> sessionsOnServer(PgConnection& db, const std::vector<SessionSummary>& sessions)
{
    constexpr std::size_t kBatch = 1000;  // far below the protocol's 65 535 parameters
    std::map<std::string, OnServer> result;
    for (std::size_t from = 0; from < sessions.size(); from += kBatch) {
        const std::size_t to = std::min(sessions.size(), from + kBatch);
        std::string placeholders;
        PgParams uuids;
        for (std::size_t i = from; i < to; ++i) {
            placeholders += (i > from ? ",$" : "$") + std::to_string(i - from + 1);
            uuids.text(sessions[i].uuid);
        }
        const PgResult r = db.query(
            "SELECT uuid, id, checksum FROM sessions WHERE complete AND uuid IN (" + placeholders + ")", uuids);
        for (int i = 0; i < r.rows(); ++i) result[r.text(i, 0)] = {r.int64(i, 1), r.text(i, 2)};
    }
    return result;
}

// One station's sync at a time, by a session-level advisory lock on the
// station's name: tried once a second (a blocking wait would outlast the
// connection's answer deadline), released when the sync ends. The lock is
// the connection's: while it is held a lost connection ends the sync.
class StationLock {
public:
    StationLock(PgConnection& db, const std::string& station, std::stop_token stop)
        : m_db(db),
          m_key(station)
    {
        for (;;) {
            m_held = m_db.query("SELECT pg_try_advisory_lock(7427, hashtext($1))", {m_key}).text(0, 0) == "t";
            if (m_held) m_db.holdServerState();
            if (m_held || stop.stop_requested()) return;
            std::this_thread::sleep_for(std::chrono::seconds(1));
        }
    }
    ~StationLock()
    {
        if (!m_held) return;
        try {
            if (m_db.isOpen()) m_db.query("SELECT pg_advisory_unlock(7427, hashtext($1))", {m_key});
        } catch (const StorageError&) {
            // The connection is gone: the server released the lock with it.
        }
        m_db.releaseServerState();
    }
    StationLock(const StationLock&) = delete;
    StationLock& operator=(const StationLock&) = delete;
    bool held() const { return m_held; }

private:
    PgConnection& m_db;
    std::string m_key;
    bool m_held = false;
};

// What a sync sends: all but the sessions still being recorded.
std::vector<SessionSummary> finishedSessions(const std::vector<SessionSummary>& all)
{
    std::vector<SessionSummary> result;
    for (const SessionSummary& s : all)
        if (s.status != SessionStatus::Recording) result.push_back(s);
    return result;
}

}  // namespace

std::string syncSummary(const SyncOutcome& outcome)
{
    const double m = static_cast<double>(outcome.samplesSent) / 1e6;
    int decimals = 0;
    if (m >= 1.0)
        decimals = 1;
    else if (outcome.samplesSent > 0)
        decimals = 1 - static_cast<int>(std::floor(std::log10(m)));
    char millions[32];
    std::snprintf(millions, sizeof millions, "%.*f", decimals, m);
    return "synced " + std::to_string(outcome.sent) + " sessions (" + millions + " M samples), " +
           std::to_string(outcome.alreadyThere) + " already there";
}

std::string sessionChecksum(SessionStore& local, std::int64_t session, ChunkCut cut)
{
    std::string lines;
    // A session of several devices: its parts', each named by its device.
    for (const SessionPart& part : local.parts(session))
        lines += part.deviceName + ' ' + sessionChecksum(local, part.id, cut) + '\n';
    if (!lines.empty()) {
        text::Md5 md5;
        md5.add(lines);
        return md5.hex();
    }
    const auto line = [&lines](const SessionStore::RawChunk& c) {
        if (!lines.empty()) lines += '\n';
        lines += chunkLine(c.firstIndex, c.count, c.samples);
    };
    if (cut == ChunkCut::Server)
        forEachServerChunk(local, session, line);
    else
        local.forEachChunk(session, line);
    text::Md5 md5;
    md5.add(lines);
    return md5.hex();
}

SyncOutcome syncToCentral(SessionStore& local, CentralStore& central, const std::string& station, std::stop_token stop,
                          const std::function<void(const SyncProgress&)>& progress)
{
    SyncOutcome outcome;
    if (central.isReplica())
        throw StorageError(central.location() +
                           " is a read-only replica of the central store: a station sends its sessions to the "
                           "primary; name the primary alone, or add target_session_attrs=read-write to the address");
    const std::string name = station.empty() ? central.connection().user() : station;
    // Two syncs of one station at once would both send what is missing and
    // collide on its keys: the second waits for the first, then finds
    // everything there.
    const StationLock lock(central.connection(), name, stop);
    if (!lock.held()) return outcome;  // stopped while waiting
    const std::vector<SessionSummary> finished = finishedSessions(local.sessions());
    const auto there = sessionsOnServer(central.connection(), finished);
    SessionUpload upload(local, central, name);
    SyncProgress done{0, static_cast<int>(finished.size())};
    // Oldest first, as they were recorded.
    for (auto s = finished.rbegin(); s != finished.rend(); ++s, ++done.done) {
        if (progress) progress(done);
        if (stop.stop_requested()) break;  // between sessions: each is whole or not sent
        const auto decisions = local.verdicts(s->id);
        if (std::ranges::any_of(decisions, [](const auto& d) { return d.role == VerdictRole::Reviewer; }))
            outcome.keptAtStation.push_back("session " + s->uuid +
                                            ": its reviewer decisions stay at the station (a reviewer decides on "
                                            "the central store: sessions --db SERVER verdict)");
        if (!text::isUuid(s->uuid)) {  // stored before imports checked them: reported, and the others go
            outcome.refused.push_back("session " + std::to_string(s->id) + " ('" + s->uuid.substr(0, 40) +
                                      "') has no valid uuid; it was not sent");
            continue;
        }
        const std::string checksum = sessionChecksum(local, s->id);
        if (const auto found = there.find(s->uuid); found != there.end()) {
            // Sent before schema 11 in the station's own chunks: its checksum
            // is over those.
            if (found->second.checksum != checksum &&
                found->second.checksum != sessionChecksum(local, s->id, ChunkCut::AsStored)) {
                outcome.refused.push_back("session " + s->uuid +
                                          " is on the central store with other samples; it was not overwritten");
                continue;
            }
            ++outcome.alreadyThere;
            try {
                if (upload.addLaterRecords(s->id, found->second.id)) ++outcome.updated;
            } catch (const StorageError& e) {
                if (!central.connection().isOpen()) throw;
                outcome.refused.push_back("the later verdicts and notes of session " + s->uuid +
                                          " were refused: " + e.what());
            }
            continue;
        }
        try {
            outcome.samplesSent += upload.send(*s, checksum);
            ++outcome.sent;
        } catch (const StorageError& e) {
            // The server refusing this session; a lost server ends the sync.
            if (!central.connection().isOpen()) throw;
            outcome.refused.push_back("session " + s->uuid + " was refused: " + e.what());
        }
    }
    if (progress) progress(done);
    return outcome;
}

int sessionsToSync(SessionStore& local, CentralStore& central)
{
    const std::vector<SessionSummary> finished = finishedSessions(local.sessions());
    return static_cast<int>(finished.size() - sessionsOnServer(central.connection(), finished).size());
}

}  // namespace tactiscope::core::storage::central
