// SessionStore: SQL for writing and reading sessions, channels and chunks.
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"
#include "core/Version.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/Schema.h"
#include "core/text/TextChecks.h"
#include "core/text/UtcTime.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace tactiscope::core::storage {
namespace {

using text::utcNow;

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
    // The schema's CHECK admits only the vocabulary's modes and statuses.
    s.metadata = {modeFromString(row.text(2)).value_or(Mode::General),  // a newer program's mode: as it came
                  row.text(3),
                  row.text(4),
                  row.text(5),
                  row.text(6),
                  row.text(7),
                  row.text(8),
                  row.text(9),
                  row.text(10),
                  row.text(11),
                  row.text(20),
                  row.isNull(22) ? 0 : row.int64(22),
                  row.text(23)};
    s.startedUtc = row.text(12);
    s.endedUtc = row.text(13);
    s.status = sessionStatusFromString(row.text(14)).value_or(SessionStatus::Interrupted);
    s.verdict = verdictFromString(row.text(15));
    s.appVersion = row.text(16);
    s.sampleRate_hz = row.real(17);
    s.sampleCount = static_cast<std::uint64_t>(row.int64(18));
    s.eventCount = static_cast<std::uint64_t>(row.int64(19));
    s.devices = static_cast<std::size_t>(row.int64(21));
    s.unjudged = row.text(24);
    s.metadata.signalSetup = row.text(25);
    return s;
}

// SQL for a session's sample count: the end of its last chunk or last gap,
// whichever ends later; both are index lookups on the primary keys.
std::string sampleEndSql(std::string_view session)
{
    const std::string id(session);
    return "max(coalesce((SELECT first_index + count FROM chunks WHERE session_id = " + id +
           " ORDER BY first_index DESC LIMIT 1), 0), coalesce((SELECT first_index + count FROM gaps WHERE session_id "
           "= " +
           id + " ORDER BY first_index DESC LIMIT 1), 0))";
}

const std::string& summaryQuery()
{
    static const std::string sql =
        "SELECT id, uuid, mode, subject, operator, site, notes, device_model, device_serial, device_firmware, "
        "profile_json, calibrations_json, started_utc, ended_utc, status, verdict, app_version, "
        "(SELECT sample_rate_hz FROM channels WHERE session_id = s.id AND position = 0), " +
        sampleEndSql("s.id") +
        // A session of several devices counts its parts' events.
        ", (SELECT count(*) FROM events WHERE session_id = s.id AND analysis = 'live') + (SELECT count(*) FROM "
        "events e JOIN sessions p ON e.session_id = p.id WHERE p.parent_id = s.id AND e.analysis = 'live'), "
        "trigger_setup, "
        "(SELECT count(*) FROM sessions p WHERE p.parent_id = s.id), parent_id, device_name, unjudged, signal_setup "
        "FROM sessions s ";
    return sql;
}

// A chunk holds at most this many samples per channel (unless one block is
// larger): blocks of a commit are merged up to it, so an hour is a few
// thousand rows rather than one per device frame.
constexpr std::uint64_t kChunkSamples = 4096;

}  // namespace

SessionStore::SessionStore(const std::string& path, Database::Access access)
    : m_db(path, access)
{
    m_versionFound = prepareSchema(m_db);
    if (access == Database::Access::ReadOnly && m_versionFound < kSchemaVersion) {
        // An older store is read as this build reads a current one, through
        // a private copy brought up to date: the store itself is unchanged.
        m_db.readThroughPrivateCopy(path + " has an older store version (" + std::to_string(m_versionFound) +
                                    "): read through a private copy brought up to version " +
                                    std::to_string(kSchemaVersion) + "; `tactiscope-cli sessions --db " + path +
                                    " upgrade` updates the store itself");
        prepareSchema(m_db);
        buildPyramidsOfVersion1();
        m_db.exec("PRAGMA query_only = 1");
        return;
    }
    if (access != Database::Access::ReadWrite) return;
    buildPyramidsOfVersion1();
    if (const auto lock = RecorderLock::tryAcquire(path)) markCrashedSessionsInterrupted();
}

void SessionStore::buildPyramidsOfVersion1()
{
    if (m_versionFound == 0 || m_versionFound >= 2) return;
    // Version 1 had no pyramid: build it for the sessions it holds.
    Transaction transaction(m_db);
    auto ids = m_db.prepare("SELECT id FROM sessions");
    while (ids.step()) rebuildPyramids(ids.int64(0));
    transaction.commit();
}

namespace {

class StoreSnapshot : public SessionSource::Snapshot {
public:
    explicit StoreSnapshot(Database& db)
        : m_snapshot(db)
    {
    }

private:
    ReadSnapshot m_snapshot;
};

}  // namespace

std::unique_ptr<SessionSource::Snapshot> SessionStore::snapshot()
{
    return std::make_unique<StoreSnapshot>(m_db);
}

void SessionStore::deleteSession(std::int64_t session)
{
    const auto summary = this->session(session);
    if (!summary) throw StorageError("there is no session " + std::to_string(session));
    // Opening read-write marked crashed recordings interrupted, so one still
    // "recording" has a live recorder.
    if (summary->status == SessionStatus::Recording)
        throw StorageError("session " + std::to_string(session) + " is being recorded; stop the recording first");
    if (const auto refusal = partDeletionRefusal(*summary)) throw StorageError(*refusal);
    m_db.prepare("DELETE FROM sessions WHERE id = ?").bind(1, session).run();  // cascades
}

int SessionStore::markCrashedSessionsInterrupted()
{
    m_db.prepare("UPDATE sessions SET status = ? WHERE status = ?")
        .bind(1, toString(SessionStatus::Interrupted))
        .bind(2, toString(SessionStatus::Recording))
        .run();
    return m_db.changes();
}

namespace {

// What a store holds is sent to the central store and read everywhere: its
// text must be UTF-8 without NUL (a server refuses the one and cuts the
// other), its uuid a uuid (one holding '"' once stopped every later sync).
void check(std::string_view text, const std::string& what)
{
    if (const auto problem = text::textProblem(text))
        throw StoreInputError("the session's " + what + " cannot be stored: " + *problem +
                              " (text must be UTF-8 without NUL); nothing was stored");
}

void refuseUnstorableText(std::span<const ChannelDescriptor> channels)
{
    for (const ChannelDescriptor& c : channels) {
        check(c.name, "channel name");
        check(c.unit, "channel unit '" + c.name + "'");
    }
}

void refuseUnstorableText(const SessionMetadata& m, std::span<const ChannelDescriptor> channels,
                          const SessionOrigin& origin)
{
    check(m.subject, "subject");
    check(m.operatorName, "operator");
    check(m.site, "site");
    check(m.notes, "notes");
    check(m.deviceModel, "device model");
    check(m.deviceSerial, "device serial number");
    check(m.deviceFirmware, "device firmware");
    check(m.profileJson, "sensor profile");
    check(m.calibrationsJson, "calibrations");
    check(m.trigger, "trigger");
    check(m.deviceName, "device name");
    check(origin.startedUtc, "start time");
    check(origin.appVersion, "app version");
    refuseUnstorableText(channels);
    if (!origin.uuid.empty() && !text::isUuid(origin.uuid))
        throw StoreInputError("the session's uuid '" + origin.uuid.substr(0, 40) +
                              "' is not a uuid (8-4-4-4-12 hexadecimal digits); nothing was stored");
}

// `block` with `channels` channels, those it lacks NaN.
SampleBlock withChannels(const SampleBlock& block, std::size_t channels)
{
    if (block.channelCount() >= channels) return block;
    SampleBlock padded(channels, block.sampleCount(), block.t0_s(), block.dt_s(), block.firstSampleIndex(),
                       block.sequence());
    for (std::size_t c = 0; c < channels; ++c) {
        auto out = padded.channel(c);
        if (c < block.channelCount())
            std::ranges::copy(block.channel(c), out.begin());
        else
            std::ranges::fill(out, std::numeric_limits<double>::quiet_NaN());
    }
    return padded;
}

}  // namespace

std::int64_t SessionStore::insertSessionRow(const SessionMetadata& m, const SessionOrigin& origin)
{
    if (m.partOf != 0) refuseUnknownParent(m.partOf);
    auto session =
        m_db.prepare("INSERT INTO sessions (uuid, mode, subject, operator, site, notes, device_model, device_serial, "
                     "device_firmware, profile_json, calibrations_json, started_utc, status, app_version, "
                     "trigger_setup, parent_id, device_name, signal_setup) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                     "?, ?, ?, ?, ?, "
                     "?)");
    if (m.partOf != 0)
        session.bind(16, m.partOf);
    else
        session.bindNull(16);
    session.bind(1, origin.uuid.empty() ? newUuid() : origin.uuid)
        .bind(2, toString(m.mode))
        .bind(3, m.subject)
        .bind(4, m.operatorName)
        .bind(5, m.site)
        .bind(6, m.notes)
        .bind(7, m.deviceModel)
        .bind(8, m.deviceSerial)
        .bind(9, m.deviceFirmware)
        .bind(10, m.profileJson)
        .bind(11, m.calibrationsJson)
        .bind(12, origin.startedUtc.empty() ? utcNow() : origin.startedUtc)
        .bind(13, toString(SessionStatus::Recording))
        .bind(14, origin.appVersion.empty() ? std::string(versionString()) : origin.appVersion)
        .bind(15, m.trigger)
        .bind(17, m.deviceName)
        .bind(18, m.signalSetup)
        .run();
    return m_db.lastInsertId();
}

std::int64_t SessionStore::beginSession(const SessionMetadata& m, std::span<const ChannelDescriptor> channels,
                                        double sampleRate_hz, const SessionOrigin& origin)
{
    if (channels.empty()) throw StorageError("a session needs at least one channel");
    if (!(sampleRate_hz > 0.0) || !std::isfinite(sampleRate_hz))
        throw StorageError("a session needs a positive sample rate");
    refuseUnstorableText(m, channels, origin);
    Transaction transaction(m_db);
    const std::int64_t id = insertSessionRow(m, origin);
    insertChannelRows(id, channels, 0, sampleRate_hz);
    transaction.commit();
    return id;
}

void SessionStore::insertChannelRows(std::int64_t session, std::span<const ChannelDescriptor> channels,
                                     std::size_t firstPosition, double sampleRate_hz)
{
    auto insert = m_db.prepare("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) "
                               "VALUES (?, ?, ?, ?, ?, ?, ?)");
    for (std::size_t c = 0; c < channels.size(); ++c) {
        insert.bind(1, session)
            .bind(2, static_cast<std::int64_t>(firstPosition + c))
            .bind(3, channels[c].name)
            .bind(4, channels[c].unit)
            .bind(5, toString(channels[c].kind))
            .bind(6, sampleRate_hz)
            .bind(7, roleWord(channels[c].role))
            .run();
    }
}

void SessionStore::addChannels(std::int64_t session, std::span<const ChannelDescriptor> added)
{
    if (added.empty()) return;
    refuseUnstorableText(added);
    const auto existing = channels(session);
    if (existing.empty()) throw StorageError("session " + std::to_string(session) + " has no channels to add to");
    Transaction transaction(m_db);
    insertChannelRows(session, added, existing.size(), existing.front().sampleRate_hz);
    padChunks(session, existing.size(), added.size());
    transaction.commit();
}

lod::LodTable SessionStore::pyramid(std::int64_t session, std::size_t channel)
{
    return lod::LodTable(m_db, session, channel, [this, session, channel](std::uint64_t first, std::uint64_t count) {
        return readChannel(session, channel, first, count);
    });
}

void SessionStore::appendChunk(std::int64_t session, std::span<const SampleBlock> run)
{
    std::uint64_t samples = 0;
    for (const SampleBlock& block : run) samples += block.sampleCount();
    m_db.prepare("INSERT INTO chunks (session_id, first_index, first_time_s, count, samples) VALUES (?, ?, ?, ?, ?)")
        .bind(1, session)
        .bind(2, static_cast<std::int64_t>(run.front().firstSampleIndex()))
        .bind(3, run.front().t0_s())
        .bind(4, static_cast<std::int64_t>(samples))
        .bindBlob(5, encodeChunk(run))
        .run();
}

void SessionStore::appendBlocks(std::int64_t session, std::span<const SampleBlock> given)
{
    if (given.empty()) return;
    Transaction transaction(m_db);
    const std::size_t channelCount = channels(session).size();
    // A block from before the session gained channels holds them as holes.
    std::vector<SampleBlock> padded;
    if (std::ranges::any_of(given, [&](const SampleBlock& b) { return b.channelCount() < channelCount; }))
        for (const SampleBlock& block : given) padded.push_back(withChannels(block, channelCount));
    const std::span<const SampleBlock> blocks = padded.empty() ? given : std::span<const SampleBlock>(padded);
    std::uint64_t end = sampleCount(session);
    std::vector<lod::LodBuilder> pyramids;
    for (std::size_t c = 0; c < channelCount; ++c) pyramids.push_back(pyramid(session, c).builderAt(end));
    auto gap = m_db.prepare("INSERT INTO gaps VALUES (?, ?, ?)");
    std::vector<float> values;
    std::size_t runFirst = 0;  // blocks [runFirst, b) are contiguous and go into one chunk
    std::uint64_t runSamples = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const SampleBlock& block = blocks[b];
        if (block.channelCount() != channelCount)
            throw StorageError("a block has " + std::to_string(block.channelCount()) + " channels, session " +
                               std::to_string(session) + " has " + std::to_string(channelCount) +
                               "; nothing of this batch was stored");
        if (block.firstSampleIndex() < end)
            throw StorageError("samples arrived out of order (index " + std::to_string(block.firstSampleIndex()) +
                               " after " + std::to_string(end) + "); nothing of this batch was stored");
        const bool lost = block.firstSampleIndex() > end;
        if (b > runFirst && (lost || runSamples + block.sampleCount() > kChunkSamples || block.empty())) {
            appendChunk(session, blocks.subspan(runFirst, b - runFirst));
            runFirst = b;
            runSamples = 0;
        }
        if (block.empty()) {
            runFirst = b + 1;
            continue;
        }
        if (lost) {
            const std::uint64_t count = block.firstSampleIndex() - end;
            gap.bind(1, session)
                .bind(2, static_cast<std::int64_t>(end))
                .bind(3, static_cast<std::int64_t>(count))
                .run();
            for (auto& p : pyramids) p.addMissing(count);
        }
        for (std::size_t c = 0; c < channelCount; ++c) {
            const auto samples = block.channel(c);
            values.assign(samples.begin(), samples.end());  // binary32, as stored
            pyramids[c].add(values);
        }
        runSamples += block.sampleCount();
        end = block.endSampleIndex();
    }
    if (runFirst < blocks.size()) appendChunk(session, blocks.subspan(runFirst));
    for (std::size_t c = 0; c < channelCount; ++c) pyramid(session, c).write(pyramids[c].takeChangedRows());
    transaction.commit();
}

void SessionStore::markLostUntil(std::int64_t session, std::uint64_t endIndex)
{
    Transaction transaction(m_db);
    const std::uint64_t end = sampleCount(session);
    if (endIndex <= end) return;
    m_db.prepare("INSERT INTO gaps VALUES (?, ?, ?)")
        .bind(1, session)
        .bind(2, static_cast<std::int64_t>(end))
        .bind(3, static_cast<std::int64_t>(endIndex - end))
        .run();
    const std::size_t channelCount = channels(session).size();
    for (std::size_t c = 0; c < channelCount; ++c) {
        auto table = pyramid(session, c);
        auto builder = table.builderAt(end);
        builder.addMissing(endIndex - end);
        table.write(builder.takeChangedRows());
    }
    transaction.commit();
}

void SessionStore::rebuildPyramids(std::int64_t session)
{
    m_db.prepare("DELETE FROM lod WHERE session_id = ?").bind(1, session).run();
    const std::uint64_t end = sampleCount(session);
    constexpr std::uint64_t kWindow = 1 << 20;
    std::vector<float> values;
    for (std::size_t c = 0; c < channels(session).size(); ++c) {
        lod::LodBuilder builder;
        for (std::uint64_t first = 0; first < end; first += kWindow) {
            const auto samples = readChannel(session, c, first, kWindow);
            values.assign(samples.begin(), samples.end());  // lost samples are NaN: counted, no value
            builder.add(values);
        }
        pyramid(session, c).write(builder.takeChangedRows());
    }
}

void SessionStore::endSession(std::int64_t session, SessionStatus status, std::optional<std::string> endedUtc)
{
    m_db.prepare("UPDATE sessions SET status = ?, ended_utc = ? WHERE id = ?")
        .bind(1, toString(status))
        .bind(2, endedUtc.value_or(utcNow()))
        .bind(3, session)
        .run();
}

void SessionStore::setStartedUtc(std::int64_t session, const std::string& startedUtc)
{
    m_db.prepare("UPDATE sessions SET started_utc = ? WHERE id = ?").bind(1, startedUtc).bind(2, session).run();
}

void SessionStore::setSignalSetup(std::int64_t session, const std::string& setupJson)
{
    m_db.prepare("UPDATE sessions SET signal_setup = ? WHERE id = ?").bind(1, setupJson).bind(2, session).run();
}

void SessionStore::markUnjudged(std::int64_t session, const std::string& why)
{
    m_db.prepare("UPDATE sessions SET unjudged = ? WHERE id = ?").bind(1, why).bind(2, session).run();
}

void SessionStore::setVerdict(std::int64_t session, Verdict verdict)
{
    m_db.prepare("UPDATE sessions SET verdict = ? WHERE id = ?").bind(1, toString(verdict)).bind(2, session).run();
    if (m_db.changes() == 0) throw StorageError("there is no session " + std::to_string(session));
}

std::string SessionStore::checkIntegrity()
{
    auto check = m_db.prepare("PRAGMA integrity_check");
    return check.step() ? check.text(0) : std::string("no answer from the integrity check");
}

void SessionStore::refuseIfDamaged()
{
    std::string finding;
    try {
        auto check = m_db.prepare("PRAGMA quick_check(1)");
        finding = check.step() ? check.text(0) : std::string("no answer from the check");
    } catch (const StorageError& e) {
        finding = e.what();  // a page too damaged to even be checked
    }
    if (finding == "ok") return;
    // SQLite heads its findings "*** in database main ***" on a line of its own.
    constexpr std::string_view kHeading = "*** in database main ***";
    if (const auto at = finding.find(kHeading); at != std::string::npos) finding.erase(at, kHeading.size());
    std::ranges::replace(finding, '\n', ' ');
    while (!finding.empty() && finding.front() == ' ') finding.erase(0, 1);
    throw StoreInputError(m_db.path() + " is damaged (" + finding +
                          "); nothing was written to it. Record into another store, and export what can still be read "
                          "from this one");
}

std::vector<SessionSummary> SessionStore::sessions(const SessionFilter& filter)
{
    std::vector<SessionSummary> result;
    std::string where = "WHERE parent_id IS NULL";  // a device's part is listed in its session
    std::vector<std::string> values;
    const auto condition = [&](const std::string& value, const char* sql) {
        if (value.empty()) return;
        where += sql;
        values.push_back(value);
    };
    condition(filter.startedFrom, " AND started_utc >= ?");
    condition(filter.startedBefore, " AND started_utc < ?");
    if (filter.mode) condition(std::string(toString(*filter.mode)), " AND mode = ?");
    condition(filter.subject, " AND subject = ?");
    condition(filter.operatorName, " AND operator = ?");
    if (filter.verdict) condition(std::string(toString(*filter.verdict)), " AND verdict = ?");
    if (!filter.station.empty()) return result;  // a station's file holds its own sessions, of no station named
    // A crashed recording is listed interrupted (below): asked for either, both are read.
    if (filter.status == SessionStatus::Interrupted)
        where += " AND status IN ('interrupted', 'recording')";
    else if (filter.status)
        condition(std::string(toString(*filter.status)), " AND status = ?");
    if (!filter.text.empty()) {
        // One parameter, numbered, used for every searched column.
        const std::string like = " LIKE ?" + std::to_string(values.size() + 1) + " ESCAPE '\\'";
        where += " AND (subject" + like + " OR operator" + like + " OR site" + like + " OR notes" + like +
                 " OR verdict" + like + " OR (unjudged <> '' AND ('not judged: ' || unjudged)" + like + ")" +
                 " OR device_serial" + like + ")";
        values.push_back(textSearchPattern(filter.text));
    }
    if (filter.after) {
        where += " AND (started_utc, id) < (SELECT started_utc, id FROM sessions WHERE id = ?)";
        values.push_back(std::to_string(*filter.after));
    }
    // LIMIT -1: all of them.
    const int limit = static_cast<int>(values.size() + 1);
    auto query =
        m_db.prepare(summaryQuery() + where + " ORDER BY started_utc DESC, id DESC LIMIT ?" + std::to_string(limit));
    for (std::size_t i = 0; i < values.size(); ++i) query.bind(static_cast<int>(i + 1), values[i]);
    query.bind(limit, filter.limit > 0 ? static_cast<std::int64_t>(filter.limit) : std::int64_t{-1});
    while (query.step()) result.push_back(summaryFrom(query));
    for (SessionSummary& summary : result) fillFromLongestPart(summary);
    showCrashedRecordingsInterrupted(result);
    if (filter.status) std::erase_if(result, [&](const SessionSummary& s) { return s.status != *filter.status; });
    return result;
}

// A session still marked "recording" while no recorder holds the store was
// cut short by a crash; a reader (which may not mark it, see the
// constructor) shows it as what it is, so a list, an export or a report of
// it never says it is being recorded.
void SessionStore::showCrashedRecordingsInterrupted(std::span<SessionSummary> summaries)
{
    const auto recording = [](const SessionSummary& s) { return s.status == SessionStatus::Recording; };
    if (std::none_of(summaries.begin(), summaries.end(), recording) || RecorderLock::isHeld(m_db.path())) return;
    for (SessionSummary& s : summaries)
        if (recording(s)) s.status = SessionStatus::Interrupted;
}

std::optional<SessionSummary> SessionStore::session(std::int64_t id)
{
    auto query = m_db.prepare(summaryQuery() + "WHERE id = ?");
    query.bind(1, id);
    if (!query.step()) return std::nullopt;
    SessionSummary summary = summaryFrom(query);
    fillFromLongestPart(summary);
    showCrashedRecordingsInterrupted(std::span(&summary, 1));
    return summary;
}

SessionSource::Rights SessionStore::rights() const
{
    if (m_db.access() == Database::Access::ReadWrite) return {};
    const std::string why = "the store is open read-only";
    return {why, why, why, why};
}

std::optional<std::int64_t> SessionStore::sessionWithUuid(const std::string& uuid)
{
    auto query = m_db.prepare("SELECT id FROM sessions WHERE uuid = ?");
    query.bind(1, uuid);
    if (!query.step()) return std::nullopt;
    return query.int64(0);
}

std::optional<std::int64_t> SessionStore::lastSession()
{
    // The primary key walked from its end: the first that is no part.
    auto query = m_db.prepare("SELECT id FROM sessions WHERE parent_id IS NULL ORDER BY id DESC LIMIT 1");
    if (!query.step()) return std::nullopt;
    return query.int64(0);
}

std::vector<StoredChannel> SessionStore::channels(std::int64_t session)
{
    m_layout.check(session);
    std::vector<StoredChannel> result;
    auto query = m_db.prepare(
        "SELECT name, unit, kind, sample_rate_hz, role FROM channels WHERE session_id = ? ORDER BY position");
    query.bind(1, session);
    while (query.step()) {
        const auto kind = channelKindFromString(query.text(2)).value_or(ChannelKind::Other);
        result.push_back({{query.text(0), query.text(1), kind, channelRoleFromString(query.text(4))}, query.real(3)});
    }
    return result;
}

std::uint64_t SessionStore::sampleCount(std::int64_t session)
{
    m_layout.check(session);
    auto query = m_db.prepare("SELECT " + sampleEndSql("?1"));
    query.bind(1, session);
    return query.step() ? static_cast<std::uint64_t>(query.int64(0)) : 0;
}

std::vector<SampleGap> SessionStore::gaps(std::int64_t session)
{
    m_layout.check(session);
    std::vector<SampleGap> result;
    auto query = m_db.prepare("SELECT first_index, count FROM gaps WHERE session_id = ? ORDER BY first_index");
    query.bind(1, session);
    while (query.step())
        result.push_back({static_cast<std::uint64_t>(query.int64(0)), static_cast<std::uint64_t>(query.int64(1))});
    return result;
}

std::size_t SessionStore::readChannels(std::int64_t session, std::span<const std::size_t> channels,
                                       std::uint64_t firstIndex, std::uint64_t count,
                                       std::vector<std::vector<double>>& out)
{
    const ReadSnapshot snapshot(m_db);
    const std::size_t channelCount = this->channels(session).size();
    for (const std::size_t channel : channels)
        if (channel >= channelCount)
            throw StorageError("session " + std::to_string(session) + " has no channel " + std::to_string(channel));
    const std::uint64_t end = std::min(sampleCount(session), firstIndex + count);
    const std::size_t n = firstIndex < end ? static_cast<std::size_t>(end - firstIndex) : 0;
    // The session's layout is checked (channels() above): no count read
    // here is damaged; a read is still bounded by what a computer holds.
    if (n > kMostSamplesPerRead)
        throw StoreInputError("session " + std::to_string(session) + " would need " + std::to_string(n) +
                              " samples read at once, more than a computer holds");
    out.resize(channels.size());
    // NaN first: whatever no chunk covers is a gap.
    for (auto& samples : out) samples.assign(n, std::numeric_limits<double>::quiet_NaN());
    if (n == 0) return 0;
    // The chunk holding firstIndex starts at or before it; the primary key
    // makes both lookups index searches, not scans.
    auto start = m_db.prepare("SELECT max(first_index) FROM chunks WHERE session_id = ? AND first_index <= ?");
    start.bind(1, session).bind(2, static_cast<std::int64_t>(firstIndex));
    const std::int64_t from = start.step() && !start.isNull(0) ? start.int64(0) : 0;
    auto query = m_db.prepare("SELECT first_index, count, samples FROM chunks "
                              "WHERE session_id = ? AND first_index >= ? AND first_index < ? ORDER BY first_index");
    query.bind(1, session).bind(2, from).bind(3, static_cast<std::int64_t>(end));
    while (query.step()) {
        const auto chunkFirst = static_cast<std::uint64_t>(query.int64(0));
        const auto chunkCount = static_cast<std::uint64_t>(query.int64(1));
        const std::uint64_t begin = std::max(chunkFirst, firstIndex);
        const std::uint64_t stop = std::min(chunkFirst + chunkCount, end);
        if (stop <= begin) continue;
        const auto blob = query.blob(2);
        for (std::size_t k = 0; k < channels.size(); ++k)
            decodeChunkChannel(blob, channelCount, chunkCount, channels[k], begin - chunkFirst,
                               std::span(out[k]).subspan(begin - firstIndex, stop - begin));
        ++m_chunksRead;
    }
    return n;
}

void SessionStore::forEachChunk(std::int64_t session, const std::function<void(const RawChunk&)>& visit)
{
    m_layout.check(session);
    auto query = m_db.prepare(
        "SELECT first_index, first_time_s, count, samples FROM chunks WHERE session_id = ? ORDER BY first_index");
    query.bind(1, session);
    while (query.step())
        visit({static_cast<std::uint64_t>(query.int64(0)), query.real(1), static_cast<std::uint64_t>(query.int64(2)),
               query.blob(3)});
}

void SessionStore::forEachLodRow(std::int64_t session, const std::function<void(const RawLodRow&)>& visit)
{
    auto query = m_db.prepare("SELECT channel, level, first_bucket, count, buckets FROM lod WHERE session_id = ? "
                              "ORDER BY channel, level, first_bucket");
    query.bind(1, session);
    while (query.step())
        visit({query.int64(0), query.int64(1), static_cast<std::uint64_t>(query.int64(2)),
               static_cast<std::uint64_t>(query.int64(3)), query.blob(4)});
}

std::vector<OverviewPoint> SessionStore::overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                                  std::uint64_t count, std::size_t points)
{
    const ReadSnapshot snapshot(m_db);  // samples and pyramid of the same commit
    if (channel >= channels(session).size())
        throw StorageError("session " + std::to_string(session) + " has no channel " + std::to_string(channel));
    const std::uint64_t end = std::min(sampleCount(session), firstIndex + count);
    if (firstIndex >= end) return {};
    return pyramid(session, channel).overview(firstIndex, end, points);
}

}  // namespace tactiscope::core::storage
