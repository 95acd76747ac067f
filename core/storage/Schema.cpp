// Schema creation and migrations. A migration is the SQL that takes the
// store from version N to N + 1; each runs in its own transaction.
#include "core/storage/Schema.h"

#include <array>
#include <map>
#include <set>
#include <string>

namespace tactiscope::core::storage {
namespace {

// Version 0 → 1: the first schema.
constexpr const char* kVersion1 = R"sql(
CREATE TABLE sessions (
    id              INTEGER PRIMARY KEY,
    uuid            TEXT NOT NULL UNIQUE,
    mode            TEXT NOT NULL CHECK (mode IN ('panel-scan', 'palpation', 'capacitive')),
    subject         TEXT NOT NULL DEFAULT '',
    operator        TEXT NOT NULL DEFAULT '',
    site            TEXT NOT NULL DEFAULT '',
    notes           TEXT NOT NULL DEFAULT '',
    started_utc     TEXT NOT NULL,
    ended_utc       TEXT,
    status          TEXT NOT NULL CHECK (status IN ('recording', 'complete', 'interrupted')),
    verdict         TEXT NOT NULL DEFAULT '',
    device_model    TEXT NOT NULL DEFAULT '',
    device_serial   TEXT NOT NULL DEFAULT '',
    device_firmware TEXT NOT NULL DEFAULT '',
    profile_json    TEXT NOT NULL DEFAULT '',
    app_version     TEXT NOT NULL
);
CREATE INDEX sessions_started ON sessions (started_utc);

CREATE TABLE channels (
    session_id     INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    position       INTEGER NOT NULL,
    name           TEXT NOT NULL,
    unit           TEXT NOT NULL,
    kind           TEXT NOT NULL,
    sample_rate_hz REAL NOT NULL CHECK (sample_rate_hz > 0),
    PRIMARY KEY (session_id, position)
) WITHOUT ROWID;

CREATE TABLE chunks (
    session_id   INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index  INTEGER NOT NULL,
    first_time_s REAL NOT NULL,
    count        INTEGER NOT NULL CHECK (count > 0),
    samples      BLOB NOT NULL,
    PRIMARY KEY (session_id, first_index)
) WITHOUT ROWID;

CREATE TABLE gaps (
    session_id  INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index INTEGER NOT NULL,
    count       INTEGER NOT NULL CHECK (count > 0),
    PRIMARY KEY (session_id, first_index)
) WITHOUT ROWID;
)sql";

// Version 1 → 2: the min/max pyramid, the calibrations copied into a
// session, and the records beside the samples: events, readings,
// annotations and the calibration history. Pyramids of sessions recorded
// under version 1 are built by SessionStore after the migration.
//
// Chunks move to a rowid table with an index: in a WITHOUT ROWID table a
// key search reads whole rows that overflow their page, i.e. every BLOB it
// passes, which made listing sessions read megabytes.
constexpr const char* kVersion2 = R"sql(
ALTER TABLE sessions ADD COLUMN calibrations_json TEXT NOT NULL DEFAULT '';

CREATE TABLE chunks_v2 (
    id           INTEGER PRIMARY KEY,
    session_id   INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index  INTEGER NOT NULL,
    first_time_s REAL NOT NULL,
    count        INTEGER NOT NULL CHECK (count > 0),
    samples      BLOB NOT NULL
);
INSERT INTO chunks_v2 (session_id, first_index, first_time_s, count, samples)
    SELECT session_id, first_index, first_time_s, count, samples FROM chunks ORDER BY session_id, first_index;
DROP TABLE chunks;
ALTER TABLE chunks_v2 RENAME TO chunks;
CREATE UNIQUE INDEX chunks_by_index ON chunks (session_id, first_index);

CREATE TABLE lod (
    session_id   INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    channel      INTEGER NOT NULL,
    level        INTEGER NOT NULL,
    first_bucket INTEGER NOT NULL,
    count        INTEGER NOT NULL CHECK (count > 0),
    buckets      BLOB NOT NULL,
    PRIMARY KEY (session_id, channel, level, first_bucket)
) WITHOUT ROWID;

CREATE TABLE events (
    id            INTEGER PRIMARY KEY,
    session_id    INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    analysis      TEXT NOT NULL DEFAULT 'live',
    kind          TEXT NOT NULL CHECK (kind IN ('defect', 'contact', 'press', 'alarm', 'marker')),
    start_s       REAL NOT NULL,
    end_s         REAL NOT NULL CHECK (end_s >= start_s),
    direction     INTEGER NOT NULL DEFAULT 0 CHECK (direction IN (-1, 0, 1)),
    peak_r        REAL,
    lag_s         REAL,
    speed_m_per_s REAL,
    note          TEXT NOT NULL DEFAULT ''
);
CREATE INDEX events_by_session ON events (session_id, analysis, start_s);

CREATE TABLE readings (
    id             INTEGER PRIMARY KEY,
    session_id     INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    kind           TEXT NOT NULL CHECK (kind IN ('compliance', 'capacitive')),
    start_s        REAL NOT NULL,
    end_s          REAL NOT NULL CHECK (end_s >= start_s),
    quantity       TEXT NOT NULL,
    value          REAL NOT NULL,
    unit           TEXT NOT NULL,
    standard_error REAL,
    site           TEXT NOT NULL DEFAULT '',
    details_json   TEXT NOT NULL DEFAULT ''
);
CREATE INDEX readings_by_session ON readings (session_id, start_s);

CREATE TABLE annotations (
    id           INTEGER PRIMARY KEY,
    session_id   INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    time_s       REAL NOT NULL,
    author       TEXT NOT NULL DEFAULT '',
    text         TEXT NOT NULL,
    created_utc  TEXT NOT NULL,
    modified_utc TEXT NOT NULL
);
CREATE INDEX annotations_by_session ON annotations (session_id, time_s);

CREATE TABLE calibrations (
    id          INTEGER PRIMARY KEY,
    kind        TEXT NOT NULL,
    sensor      TEXT NOT NULL,
    operator    TEXT NOT NULL DEFAULT '',
    created_utc TEXT NOT NULL,
    r_squared   REAL NOT NULL,
    points      INTEGER NOT NULL,
    record_json TEXT NOT NULL
);
CREATE INDEX calibrations_by_sensor ON calibrations (sensor, created_utc);

CREATE TABLE session_calibrations (
    session_id     INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    calibration_id INTEGER NOT NULL REFERENCES calibrations (id) ON DELETE RESTRICT,
    PRIMARY KEY (session_id, calibration_id)
) WITHOUT ROWID;
CREATE INDEX session_calibrations_by_calibration ON session_calibrations (calibration_id);
)sql";

// Version 2 → 3: who decided a session's verdict, and the zeros the mode's
// processor read the samples on. Each verdict decision is a row:
// the automatic one (its analysis and parameters in basis_json), the
// operator's at the stop, a reviewer's later; sessions.verdict stays the
// final one, for listing and filtering. Sessions recorded before keep their
// verdict without a trail: nobody knows any more who decided it. A zero
// (e.g. a compliance probe's raw beam values with nothing pressed) applies
// from its first sample index to the next zero, so the review derives the
// same forces the operator saw.
constexpr const char* kVersion3 = R"sql(
CREATE TABLE verdicts (
    id          INTEGER PRIMARY KEY,
    session_id  INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    role        TEXT NOT NULL CHECK (role IN ('automatic', 'operator', 'reviewer')),
    verdict     TEXT NOT NULL CHECK (verdict IN ('pass', 'defects found')),
    decided_by  TEXT NOT NULL DEFAULT '',
    decided_utc TEXT NOT NULL,
    note        TEXT NOT NULL DEFAULT '',
    basis_json  TEXT NOT NULL DEFAULT ''
);
CREATE INDEX verdicts_by_session ON verdicts (session_id, id);

CREATE TABLE zeros (
    session_id  INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index INTEGER NOT NULL,
    values_json TEXT NOT NULL,
    PRIMARY KEY (session_id, first_index)
) WITHOUT ROWID;
)sql";

// Version 3 → 4: readings, like events, belong to an analysis: the
// recording's ('live'), or a re-analysis saved under a name (a palpation's
// presses read again through another profile or calibration). Existing
// readings are the recording's.
constexpr const char* kVersion4 = R"sql(
ALTER TABLE readings ADD COLUMN analysis TEXT NOT NULL DEFAULT 'live';
DROP INDEX readings_by_session;
CREATE INDEX readings_by_session ON readings (session_id, analysis, start_s);
)sql";

// Version 4 → 5: the general mode (any device, channels stored as they
// come) and the role each channel played (core/ChannelDescriptor.h), which
// the review needs to derive a mode's quantities from a device that did not
// declare its channels' kinds. A CHECK cannot be altered in SQLite: the
// sessions table is rebuilt (new, copy, drop, rename; prepareSchema() runs
// migrations with foreign keys off, so the drop cascades nowhere).
constexpr const char* kVersion5 = R"sql(
CREATE TABLE sessions_v5 (
    id                INTEGER PRIMARY KEY,
    uuid              TEXT NOT NULL UNIQUE,
    mode              TEXT NOT NULL CHECK (mode IN ('panel-scan', 'palpation', 'capacitive', 'general')),
    subject           TEXT NOT NULL DEFAULT '',
    operator          TEXT NOT NULL DEFAULT '',
    site              TEXT NOT NULL DEFAULT '',
    notes             TEXT NOT NULL DEFAULT '',
    started_utc       TEXT NOT NULL,
    ended_utc         TEXT,
    status            TEXT NOT NULL CHECK (status IN ('recording', 'complete', 'interrupted')),
    verdict           TEXT NOT NULL DEFAULT '',
    device_model      TEXT NOT NULL DEFAULT '',
    device_serial     TEXT NOT NULL DEFAULT '',
    device_firmware   TEXT NOT NULL DEFAULT '',
    profile_json      TEXT NOT NULL DEFAULT '',
    app_version       TEXT NOT NULL,
    calibrations_json TEXT NOT NULL DEFAULT ''
);
INSERT INTO sessions_v5 (id, uuid, mode, subject, operator, site, notes, started_utc, ended_utc, status, verdict,
                         device_model, device_serial, device_firmware, profile_json, app_version, calibrations_json)
    SELECT id, uuid, mode, subject, operator, site, notes, started_utc, ended_utc, status, verdict,
           device_model, device_serial, device_firmware, profile_json, app_version, calibrations_json FROM sessions;
DROP TABLE sessions;
ALTER TABLE sessions_v5 RENAME TO sessions;
CREATE INDEX sessions_started ON sessions (started_utc);

ALTER TABLE channels ADD COLUMN role TEXT NOT NULL DEFAULT ''
    CHECK (role IN ('', 'cantilever-a', 'cantilever-b', 'stiff-beam', 'soft-beam', 'displacement', 'capacitance'));
)sql";

// Version 5 → 6: triggered recordings (core/trigger). A session cut by a
// trigger says which (sessions.trigger_setup), and a `trigger` event marks
// the instant its condition began; the events table is rebuilt for the
// CHECK, its rows and ids kept.
constexpr const char* kVersion6 = R"sql(
ALTER TABLE sessions ADD COLUMN trigger_setup TEXT NOT NULL DEFAULT '';

CREATE TABLE events_v6 (
    id            INTEGER PRIMARY KEY,
    session_id    INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    analysis      TEXT NOT NULL DEFAULT 'live',
    kind          TEXT NOT NULL CHECK (kind IN ('defect', 'contact', 'press', 'alarm', 'marker', 'trigger')),
    start_s       REAL NOT NULL,
    end_s         REAL NOT NULL CHECK (end_s >= start_s),
    direction     INTEGER NOT NULL DEFAULT 0 CHECK (direction IN (-1, 0, 1)),
    peak_r        REAL,
    lag_s         REAL,
    speed_m_per_s REAL,
    note          TEXT NOT NULL DEFAULT ''
);
INSERT INTO events_v6 (id, session_id, analysis, kind, start_s, end_s, direction, peak_r, lag_s, speed_m_per_s, note)
    SELECT id, session_id, analysis, kind, start_s, end_s, direction, peak_r, lag_s, speed_m_per_s, note FROM events;
DROP TABLE events;
ALTER TABLE events_v6 RENAME TO events;
CREATE INDEX events_by_session ON events (session_id, analysis, start_s);
)sql";

// Version 6 → 7: sessions of several devices (issue 40). Such a session is
// a row like any other, with no channels of its own, and a part per
// device: a session row whose parent_id is it, holding that device's
// channels, samples, gaps and pyramid at the device's own rate and on its
// own clock, with the device's name in the session (device_name) and the
// mapping of its clock onto the session's (clock_json). Parts go with
// their session when it is deleted.
constexpr const char* kVersion7 = R"sql(
ALTER TABLE sessions ADD COLUMN parent_id INTEGER REFERENCES sessions (id) ON DELETE CASCADE;
ALTER TABLE sessions ADD COLUMN device_name TEXT NOT NULL DEFAULT '';
ALTER TABLE sessions ADD COLUMN clock_json TEXT NOT NULL DEFAULT '';
CREATE INDEX sessions_by_parent ON sessions (parent_id);
)sql";

// Version 7 → 8: a channel may be a reference force (a load cell a
// capacitive beam is calibrated against, issue 40). The channels table is
// rebuilt for the CHECK; nothing refers to its rows.
constexpr const char* kVersion8 = R"sql(
CREATE TABLE channels_v8 (
    session_id     INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    position       INTEGER NOT NULL,
    name           TEXT NOT NULL,
    unit           TEXT NOT NULL,
    kind           TEXT NOT NULL,
    sample_rate_hz REAL NOT NULL CHECK (sample_rate_hz > 0),
    role           TEXT NOT NULL DEFAULT ''
        CHECK (role IN ('', 'cantilever-a', 'cantilever-b', 'stiff-beam', 'soft-beam', 'displacement', 'capacitance',
                        'reference-force')),
    PRIMARY KEY (session_id, position)
) WITHOUT ROWID;
INSERT INTO channels_v8 (session_id, position, name, unit, kind, sample_rate_hz, role)
    SELECT session_id, position, name, unit, kind, sample_rate_hz, role FROM channels;
DROP TABLE channels;
ALTER TABLE channels_v8 RENAME TO channels;
)sql";

// Version 8 → 9: why a session of a mode that judges got no automatic
// verdict ("too short to judge (…)", "not judged: it went past a critical
// limit"), so a reviewer reads it later rather than a bare "—" (issue 52).
constexpr const char* kVersion9 = R"sql(
ALTER TABLE sessions ADD COLUMN unjudged TEXT NOT NULL DEFAULT '';
)sql";

// Version 9 → 10: a channel may be the probe's position along a panel
// scan's stroke (an encoder or a linear potentiometer, issue 55), which
// places each crossing of a dent. The channels table is rebuilt for the
// CHECK, as in version 8.
constexpr const char* kVersion10 = R"sql(
CREATE TABLE channels_v10 (
    session_id     INTEGER NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    position       INTEGER NOT NULL,
    name           TEXT NOT NULL,
    unit           TEXT NOT NULL,
    kind           TEXT NOT NULL,
    sample_rate_hz REAL NOT NULL CHECK (sample_rate_hz > 0),
    role           TEXT NOT NULL DEFAULT ''
        CHECK (role IN ('', 'cantilever-a', 'cantilever-b', 'stiff-beam', 'soft-beam', 'displacement', 'capacitance',
                        'reference-force', 'position')),
    PRIMARY KEY (session_id, position)
) WITHOUT ROWID;
INSERT INTO channels_v10 (session_id, position, name, unit, kind, sample_rate_hz, role)
    SELECT session_id, position, name, unit, kind, sample_rate_hz, role FROM channels;
DROP TABLE channels;
ALTER TABLE channels_v10 RENAME TO channels;
)sql";

// Version 10 → 11: a session's signal setup (issue 57): the filters on its
// channels, its math channels and whether its mode analysed the filtered
// channels, a JSON object (core/signal/SignalSetup.h); the samples stay as
// they came, and review reads them through it.
constexpr const char* kVersion11 = R"sql(
ALTER TABLE sessions ADD COLUMN signal_setup TEXT NOT NULL DEFAULT '';
)sql";

constexpr std::array kMigrations{kVersion1, kVersion2, kVersion3, kVersion4,  kVersion5, kVersion6,
                                 kVersion7, kVersion8, kVersion9, kVersion10, kVersion11};
static_assert(kMigrations.size() == kSchemaVersion);

std::int64_t pragma(Database& db, const char* name)
{
    auto statement = db.prepare(std::string("PRAGMA ") + name);
    return statement.step() ? statement.int64(0) : 0;
}

// A name from the store's own schema, quoted for SQL: a crafted store's
// names are not trusted.
std::string quoteName(const std::string& name)
{
    std::string quoted = "\"";
    for (const char c : name) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

// SQLite keeps foreign keys off unless a connection asks, so a plain
// `sqlite3` delete of a session leaves its rows behind, which no reader
// reaches (every one goes by its session) and which a migration's check
// would refuse. They are removed, a table at a time (a part of a session
// that is gone, then that part's own rows), and said: e.g. "1 events row".
std::string removeRowsWithoutTheirSession(Database& db)
{
    std::map<std::string, std::int64_t> removed;
    for (;;) {
        std::set<std::pair<std::string, std::int64_t>> broken;  // table, foreign key
        for (auto check = db.prepare("PRAGMA foreign_key_check"); check.step();)
            broken.emplace(check.text(0), check.int64(3));
        if (broken.empty()) break;
        std::int64_t removedThisRound = 0;
        for (const auto& [table, key] : broken) {
            auto keys = db.prepare("SELECT \"table\", \"from\", coalesce(\"to\", 'rowid') FROM "
                                   "pragma_foreign_key_list(?) WHERE id = ?");
            keys.bind(1, table).bind(2, key);
            std::string from, parent, join;
            while (keys.step()) {  // one row per column of the key
                parent = keys.text(0);
                join += (join.empty() ? "" : " AND ") + ("c." + quoteName(keys.text(2))) + " = t." +
                        quoteName(keys.text(1));
                from += (from.empty() ? "" : " AND ") + ("t." + quoteName(keys.text(1))) + " IS NOT NULL";
            }
            if (from.empty()) continue;
            db.exec("DELETE FROM " + quoteName(table) + " AS t WHERE " + from + " AND NOT EXISTS (SELECT 1 FROM " +
                    quoteName(parent) + " AS c WHERE " + join + ")");
            if (db.changes() == 0) continue;
            removed[table] += db.changes();
            removedThisRound += db.changes();
        }
        // Rows SQLite's check and this join judge apart: the migration's
        // own check refuses them, as before.
        if (removedThisRound == 0) break;
    }
    std::string said;
    for (const auto& [table, count] : removed)
        said += (said.empty() ? "" : ", ") + std::to_string(count) + " " + table + (count == 1 ? " row" : " rows");
    return said;
}

}  // namespace

int prepareSchema(Database& db, int targetVersion)
{
    // The first read is where SQLite notices a file that is not a database.
    std::int64_t tables = 0;
    try {
        auto count = db.prepare("SELECT count(*) FROM sqlite_schema");
        count.step();
        tables = count.int64(0);
    } catch (const StorageError& e) {
        throw StoreInputError(db.path() + " is not a Tactiscope session store (" + e.what() +
                              "); it was left untouched");
    }
    const std::int64_t application = pragma(db, "application_id");
    const std::int64_t version = pragma(db, "user_version");
    if (tables > 0 && application != kApplicationId)
        throw StoreInputError(db.path() + " is an SQLite file of another program, not a Tactiscope session store; " +
                              "it was left untouched");
    // No Tactiscope writes a version below 1 into a store with tables: read
    // as one, migrating it would run the migration before the first (the
    // fuzzer's finding, once an older store's reader migrated a copy).
    if (tables > 0 && version < 1)
        throw StoreInputError(db.path() + " says it is store version " + std::to_string(version) +
                              ", which no Tactiscope writes: the store is damaged; it was left untouched");
    const bool updates = db.access() == Database::Access::ReadWrite || db.readsUpdatableCopy();
    if (version > kSchemaVersion && updates)
        throw StorageError(db.path() + " was written by a newer Tactiscope (store version " + std::to_string(version) +
                           ", this build knows " + std::to_string(kSchemaVersion) +
                           "); open it read-only or update Tactiscope");
    db.exec("PRAGMA foreign_keys = ON");
    if (version >= targetVersion || !updates) {
        if (tables == 0)  // an empty file: SQLite reads it as an empty database
            throw StorageError(db.path() + " is empty: it holds no sessions yet (recording or importing into it "
                                           "makes it a session store)");
        return static_cast<int>(version);
    }
    // WAL: readers (the review window) work while the recorder writes.
    if (!db.readsUpdatableCopy()) db.exec("PRAGMA journal_mode = WAL");
    // Foreign keys off while tables are rebuilt (SQLite ignores the pragma
    // inside a transaction); each step checks them before it commits.
    db.exec("PRAGMA foreign_keys = OFF");
    try {
        if (tables > 0) {
            Transaction transaction(db);
            if (const std::string removed = removeRowsWithoutTheirSession(db); !removed.empty())
                db.addNote("updating it from store version " + std::to_string(version) + " left out " + removed +
                           " without their session (rows a delete outside Tactiscope leaves behind)");
            transaction.commit();
        }
        for (auto step = version; step < targetVersion; ++step) {
            Transaction transaction(db);
            db.exec(kMigrations[static_cast<std::size_t>(step)]);
            if (db.prepare("PRAGMA foreign_key_check").step())
                throw StorageError(db.path() + ": updating the store to version " + std::to_string(step + 1) +
                                   " would leave rows without their session; it was left at version " +
                                   std::to_string(step));
            db.exec("PRAGMA user_version = " + std::to_string(step + 1));
            db.exec("PRAGMA application_id = " + std::to_string(kApplicationId));
            transaction.commit();
        }
    } catch (...) {
        db.exec("PRAGMA foreign_keys = ON");
        throw;
    }
    db.exec("PRAGMA foreign_keys = ON");
    return static_cast<int>(version);
}

}  // namespace tactiscope::core::storage
