// SessionStore: SQL for writing and reading sessions, channels and chunks.
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"
#include "core/Version.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/Schema.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <random>

namespace tactiscope::core::storage {
namespace {

std::string utcNow()
{
    const auto now = std::chrono::system_clock::now();
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char text[64];  // roomy enough for any int the compiler imagines in a field
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                  utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(ms));
    return text;
}

// A random (version 4) UUID: the session's identity across stores, e.g.
// when a session is exported and imported elsewhere.
std::string newUuid()
{
    std::random_device entropy;
    std::mt19937_64 random((static_cast<std::uint64_t>(entropy()) << 32) ^ entropy());
    std::uint64_t high = random(), low = random();
    high = (high & ~0xF000ULL) | 0x4000ULL;      // version 4
    low = (low & ~(3ULL << 62)) | (2ULL << 62);  // RFC 4122 variant
    char text[40];
    std::snprintf(text, sizeof text, "%08llx-%04llx-%04llx-%04llx-%012llx", static_cast<unsigned long long>(high >> 32),
                  static_cast<unsigned long long>((high >> 16) & 0xFFFF),
                  static_cast<unsigned long long>(high & 0xFFFF), static_cast<unsigned long long>(low >> 48),
                  static_cast<unsigned long long>(low & 0xFFFFFFFFFFFFULL));
    return text;
}

SessionSummary summaryFrom(const Statement& row)
{
    SessionSummary s;
    s.id = row.int64(0);
    s.uuid = row.text(1);
    s.metadata = {row.text(2), row.text(3), row.text(4), row.text(5), row.text(6),
                  row.text(7), row.text(8), row.text(9), row.text(10)};
    s.startedUtc = row.text(11);
    s.endedUtc = row.text(12);
    s.status = row.text(13);
    s.verdict = row.text(14);
    s.appVersion = row.text(15);
    return s;
}

constexpr const char* kSummaryColumns =
    "SELECT id, uuid, mode, subject, operator, site, notes, device_model, device_serial, device_firmware, "
    "profile_json, started_utc, ended_utc, status, verdict, app_version FROM sessions ";

}  // namespace

std::string_view toString(SessionStatus status)
{
    switch (status) {
    case SessionStatus::Recording:
        return "recording";
    case SessionStatus::Complete:
        return "complete";
    case SessionStatus::Interrupted:
        return "interrupted";
    }
    return "interrupted";
}

SessionStore::SessionStore(const std::string& path, Database::Access access)
    : m_db(path, access)
{
    prepareSchema(m_db);
    if (access == Database::Access::ReadWrite) {
        if (const auto lock = RecorderLock::tryAcquire(path)) markCrashedSessionsInterrupted();
    }
}

void SessionStore::deleteSession(std::int64_t session)
{
    const auto summary = this->session(session);
    if (!summary) throw StorageError("there is no session " + std::to_string(session));
    // Opening read-write marked crashed recordings interrupted, so one still
    // "recording" has a live recorder.
    if (summary->status == toString(SessionStatus::Recording))
        throw StorageError("session " + std::to_string(session) + " is being recorded; stop the recording first");
    m_db.prepare("DELETE FROM sessions WHERE id = ?").bind(1, session).run();  // cascades
}

int SessionStore::markCrashedSessionsInterrupted()
{
    auto update = m_db.prepare("UPDATE sessions SET status = 'interrupted' WHERE status = 'recording'");
    update.run();
    return m_db.changes();
}

std::int64_t SessionStore::beginSession(const SessionMetadata& m, std::span<const ChannelDescriptor> channels,
                                        double sampleRate_hz)
{
    if (channels.empty()) throw StorageError("a session needs at least one channel");
    if (!(sampleRate_hz > 0.0) || !std::isfinite(sampleRate_hz))
        throw StorageError("a session needs a positive sample rate");
    Transaction transaction(m_db);
    m_db.prepare("INSERT INTO sessions (uuid, mode, subject, operator, site, notes, device_model, device_serial, "
                 "device_firmware, profile_json, started_utc, status, app_version) "
                 "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 'recording', ?)")
        .bind(1, newUuid())
        .bind(2, m.mode)
        .bind(3, m.subject)
        .bind(4, m.operatorName)
        .bind(5, m.site)
        .bind(6, m.notes)
        .bind(7, m.deviceModel)
        .bind(8, m.deviceSerial)
        .bind(9, m.deviceFirmware)
        .bind(10, m.profileJson)
        .bind(11, utcNow())
        .bind(12, std::string_view(versionString()))
        .run();
    const std::int64_t id = m_db.lastInsertId();
    auto insert = m_db.prepare("INSERT INTO channels VALUES (?, ?, ?, ?, ?, ?)");
    for (std::size_t c = 0; c < channels.size(); ++c) {
        insert.bind(1, id)
            .bind(2, static_cast<std::int64_t>(c))
            .bind(3, channels[c].name)
            .bind(4, channels[c].unit)
            .bind(5, toString(channels[c].kind))
            .bind(6, sampleRate_hz)
            .run();
    }
    transaction.commit();
    return id;
}

void SessionStore::appendBlocks(std::int64_t session, std::span<const SampleBlock> blocks)
{
    if (blocks.empty()) return;
    Transaction transaction(m_db);
    std::uint64_t end = sampleCount(session);
    auto chunk = m_db.prepare("INSERT INTO chunks VALUES (?, ?, ?, ?, ?)");
    auto gap = m_db.prepare("INSERT INTO gaps VALUES (?, ?, ?)");
    for (const SampleBlock& block : blocks) {
        if (block.sampleCount() == 0) continue;
        if (block.firstSampleIndex() < end)
            throw StorageError("samples arrived out of order (index " + std::to_string(block.firstSampleIndex()) +
                               " after " + std::to_string(end) + "); nothing of this batch was stored");
        if (block.firstSampleIndex() > end) {
            gap.bind(1, session)
                .bind(2, static_cast<std::int64_t>(end))
                .bind(3, static_cast<std::int64_t>(block.firstSampleIndex() - end))
                .run();
        }
        chunk.bind(1, session)
            .bind(2, static_cast<std::int64_t>(block.firstSampleIndex()))
            .bind(3, block.t0_s())
            .bind(4, static_cast<std::int64_t>(block.sampleCount()))
            .bindBlob(5, encodeChunk(block))
            .run();
        end = block.endSampleIndex();
    }
    transaction.commit();
}

void SessionStore::markLostUntil(std::int64_t session, std::uint64_t endIndex)
{
    const std::uint64_t end = sampleCount(session);
    if (endIndex <= end) return;
    m_db.prepare("INSERT INTO gaps VALUES (?, ?, ?)")
        .bind(1, session)
        .bind(2, static_cast<std::int64_t>(end))
        .bind(3, static_cast<std::int64_t>(endIndex - end))
        .run();
}

void SessionStore::endSession(std::int64_t session, SessionStatus status)
{
    m_db.prepare("UPDATE sessions SET status = ?, ended_utc = ? WHERE id = ?")
        .bind(1, toString(status))
        .bind(2, utcNow())
        .bind(3, session)
        .run();
}

std::string SessionStore::checkIntegrity()
{
    auto check = m_db.prepare("PRAGMA integrity_check");
    return check.step() ? check.text(0) : std::string("no answer from the integrity check");
}

std::vector<SessionSummary> SessionStore::sessions()
{
    std::vector<SessionSummary> result;
    auto query = m_db.prepare(std::string(kSummaryColumns) + "ORDER BY started_utc DESC, id DESC");
    while (query.step()) result.push_back(summaryFrom(query));
    return result;
}

std::optional<SessionSummary> SessionStore::session(std::int64_t id)
{
    auto query = m_db.prepare(std::string(kSummaryColumns) + "WHERE id = ?");
    query.bind(1, id);
    if (!query.step()) return std::nullopt;
    return summaryFrom(query);
}

std::vector<StoredChannel> SessionStore::channels(std::int64_t session)
{
    std::vector<StoredChannel> result;
    auto query =
        m_db.prepare("SELECT name, unit, kind, sample_rate_hz FROM channels WHERE session_id = ? ORDER BY position");
    query.bind(1, session);
    while (query.step()) {
        const auto kind = channelKindFromString(query.text(2)).value_or(ChannelKind::Other);
        result.push_back({{query.text(0), query.text(1), kind}, query.real(3)});
    }
    return result;
}

std::uint64_t SessionStore::sampleCount(std::int64_t session)
{
    // The last chunk or the last gap, whichever ends later; both are index
    // lookups on the primary keys.
    auto query = m_db.prepare("SELECT max(coalesce((SELECT first_index + count FROM chunks WHERE session_id = ?1 "
                              "ORDER BY first_index DESC LIMIT 1), 0), coalesce((SELECT first_index + count FROM gaps "
                              "WHERE session_id = ?1 ORDER BY first_index DESC LIMIT 1), 0))");
    query.bind(1, session);
    return query.step() ? static_cast<std::uint64_t>(query.int64(0)) : 0;
}

std::vector<SampleGap> SessionStore::gaps(std::int64_t session)
{
    std::vector<SampleGap> result;
    auto query = m_db.prepare("SELECT first_index, count FROM gaps WHERE session_id = ? ORDER BY first_index");
    query.bind(1, session);
    while (query.step())
        result.push_back({static_cast<std::uint64_t>(query.int64(0)), static_cast<std::uint64_t>(query.int64(1))});
    return result;
}

std::vector<double> SessionStore::readChannel(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                              std::uint64_t count)
{
    const std::size_t channelCount = channels(session).size();
    if (channel >= channelCount)
        throw StorageError("session " + std::to_string(session) + " has no channel " + std::to_string(channel));
    const std::uint64_t end = std::min(sampleCount(session), firstIndex + count);
    std::vector<double> result;
    if (firstIndex >= end) return result;
    result.reserve(end - firstIndex);
    // The chunk holding firstIndex starts at or before it; the primary key
    // makes both lookups index searches, not scans.
    auto start = m_db.prepare("SELECT max(first_index) FROM chunks WHERE session_id = ? AND first_index <= ?");
    start.bind(1, session).bind(2, static_cast<std::int64_t>(firstIndex));
    const std::int64_t from = start.step() && !start.isNull(0) ? start.int64(0) : 0;
    auto query = m_db.prepare("SELECT first_index, count, samples FROM chunks "
                              "WHERE session_id = ? AND first_index >= ? AND first_index < ? ORDER BY first_index");
    query.bind(1, session).bind(2, from).bind(3, static_cast<std::int64_t>(end));
    std::uint64_t next = firstIndex;
    while (query.step()) {
        const auto chunkFirst = static_cast<std::uint64_t>(query.int64(0));
        const auto chunkCount = static_cast<std::uint64_t>(query.int64(1));
        if (chunkFirst + chunkCount <= next) continue;
        if (chunkFirst > next) result.insert(result.end(), chunkFirst - next, std::numeric_limits<double>::quiet_NaN());
        next = std::max(next, chunkFirst);
        const std::uint64_t take = std::min(chunkFirst + chunkCount, end) - next;
        decodeChunkChannel(query.blob(2), channelCount, chunkCount, channel, next - chunkFirst, take, result);
        next += take;
    }
    result.resize(end - firstIndex, std::numeric_limits<double>::quiet_NaN());
    return result;
}

}  // namespace tactiscope::core::storage
