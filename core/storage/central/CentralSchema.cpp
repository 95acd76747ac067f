// Central schema, roles and row-level security, idempotent.
#include "core/storage/central/CentralSchema.h"

namespace tactiscope::core::storage::central {
namespace {

// Every statement may run again: IF NOT EXISTS, and roles and policies
// created only where missing.
constexpr const char* kSchema = R"sql(
DO $$ BEGIN
    IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'tactiscope_station') THEN
        CREATE ROLE tactiscope_station NOLOGIN;
    END IF;
    IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'tactiscope_reviewer') THEN
        CREATE ROLE tactiscope_reviewer NOLOGIN;
    END IF;
END $$;

CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL);

CREATE TABLE IF NOT EXISTS sessions (
    id                BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    uuid              TEXT NOT NULL UNIQUE,
    station           TEXT NOT NULL DEFAULT current_user,
    station_id        BIGINT NOT NULL DEFAULT 0,
    complete          BOOLEAN NOT NULL DEFAULT false,
    checksum          TEXT NOT NULL DEFAULT '',
    mode              TEXT NOT NULL CHECK (mode IN ('panel-scan', 'palpation', 'capacitive')),
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
    calibrations_json TEXT NOT NULL DEFAULT '',
    app_version       TEXT NOT NULL
);
-- Schema 2: the session's id in its station's store.
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS station_id BIGINT NOT NULL DEFAULT 0;
-- Schema 3: the general mode, and the role each channel played.
ALTER TABLE sessions DROP CONSTRAINT IF EXISTS sessions_mode_check;
ALTER TABLE sessions ADD CONSTRAINT sessions_mode_check
    CHECK (mode IN ('panel-scan', 'palpation', 'capacitive', 'general'));
CREATE INDEX IF NOT EXISTS sessions_started ON sessions (started_utc);
CREATE INDEX IF NOT EXISTS sessions_by_station ON sessions (station, started_utc);

CREATE TABLE IF NOT EXISTS channels (
    session_id     BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    position       INTEGER NOT NULL,
    name           TEXT NOT NULL,
    unit           TEXT NOT NULL,
    kind           TEXT NOT NULL,
    sample_rate_hz DOUBLE PRECISION NOT NULL CHECK (sample_rate_hz > 0),
    PRIMARY KEY (session_id, position)
);
ALTER TABLE channels ADD COLUMN IF NOT EXISTS role TEXT NOT NULL DEFAULT '';

CREATE TABLE IF NOT EXISTS gaps (
    session_id  BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index BIGINT NOT NULL,
    count       BIGINT NOT NULL CHECK (count > 0),
    PRIMARY KEY (session_id, first_index)
);

CREATE TABLE IF NOT EXISTS events (
    id            BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    session_id    BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    analysis      TEXT NOT NULL DEFAULT 'live',
    kind          TEXT NOT NULL CHECK (kind IN ('defect', 'contact', 'press', 'alarm', 'marker')),
    start_s       DOUBLE PRECISION NOT NULL,
    end_s         DOUBLE PRECISION NOT NULL CHECK (end_s >= start_s),
    direction     INTEGER NOT NULL DEFAULT 0 CHECK (direction IN (-1, 0, 1)),
    peak_r        DOUBLE PRECISION,
    lag_s         DOUBLE PRECISION,
    speed_m_per_s DOUBLE PRECISION,
    note          TEXT NOT NULL DEFAULT ''
);
CREATE INDEX IF NOT EXISTS events_by_session ON events (session_id, analysis, start_s);
-- Schema 6: triggered recordings: the trigger a session was cut by, and
-- the instant its condition began as a 'trigger' event.
ALTER TABLE events DROP CONSTRAINT IF EXISTS events_kind_check;
ALTER TABLE events ADD CONSTRAINT events_kind_check
    CHECK (kind IN ('defect', 'contact', 'press', 'alarm', 'marker', 'trigger'));
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS trigger_setup TEXT NOT NULL DEFAULT '';
-- Schema 7: sessions of several devices (issue 40): each device a part, a
-- session row whose parent_id is its session, with the device's name and
-- the mapping of its clock onto the session's.
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS parent_id BIGINT REFERENCES sessions (id) ON DELETE CASCADE;
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS device_name TEXT NOT NULL DEFAULT '';
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS clock_json TEXT NOT NULL DEFAULT '';
CREATE INDEX IF NOT EXISTS sessions_by_parent ON sessions (parent_id);
-- Schema 8: why a session of a mode that judges got no automatic verdict.
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS unjudged TEXT NOT NULL DEFAULT '';
-- Schema 12: a session's signal setup (issue 57): its filters and math
-- channels, as JSON (core/signal/SignalSetup.h).
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS signal_setup TEXT NOT NULL DEFAULT '';

CREATE TABLE IF NOT EXISTS readings (
    id             BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    session_id     BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    analysis       TEXT NOT NULL DEFAULT 'live',
    kind           TEXT NOT NULL CHECK (kind IN ('compliance', 'capacitive')),
    start_s        DOUBLE PRECISION NOT NULL,
    end_s          DOUBLE PRECISION NOT NULL CHECK (end_s >= start_s),
    quantity       TEXT NOT NULL,
    value          DOUBLE PRECISION NOT NULL,
    unit           TEXT NOT NULL,
    standard_error DOUBLE PRECISION,
    site           TEXT NOT NULL DEFAULT '',
    details_json   TEXT NOT NULL DEFAULT ''
);
CREATE INDEX IF NOT EXISTS readings_by_session ON readings (session_id, analysis, start_s);

CREATE TABLE IF NOT EXISTS annotations (
    id           BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    session_id   BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    time_s       DOUBLE PRECISION NOT NULL,
    author       TEXT NOT NULL DEFAULT '',
    text         TEXT NOT NULL,
    created_utc  TEXT NOT NULL,
    modified_utc TEXT NOT NULL,
    added_by     TEXT NOT NULL DEFAULT current_user
);
CREATE INDEX IF NOT EXISTS annotations_by_session ON annotations (session_id, time_s);

CREATE TABLE IF NOT EXISTS verdicts (
    id          BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    session_id  BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    role        TEXT NOT NULL CHECK (role IN ('automatic', 'operator', 'reviewer')),
    verdict     TEXT NOT NULL CHECK (verdict IN ('pass', 'defects found')),
    decided_by  TEXT NOT NULL DEFAULT '',
    decided_utc TEXT NOT NULL,
    note        TEXT NOT NULL DEFAULT '',
    basis_json  TEXT NOT NULL DEFAULT '',
    added_by    TEXT NOT NULL DEFAULT current_user
);
CREATE INDEX IF NOT EXISTS verdicts_by_session ON verdicts (session_id, id);

CREATE TABLE IF NOT EXISTS zeros (
    session_id  BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    first_index BIGINT NOT NULL,
    values_json TEXT NOT NULL,
    PRIMARY KEY (session_id, first_index)
);

CREATE TABLE IF NOT EXISTS calibrations (
    id          BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    station     TEXT NOT NULL DEFAULT current_user,
    kind        TEXT NOT NULL,
    sensor      TEXT NOT NULL,
    operator    TEXT NOT NULL DEFAULT '',
    created_utc TEXT NOT NULL,
    r_squared   DOUBLE PRECISION NOT NULL,
    points      INTEGER NOT NULL,
    record_json TEXT NOT NULL,
    UNIQUE (station, sensor, created_utc, kind)
);
CREATE INDEX IF NOT EXISTS calibrations_by_sensor ON calibrations (sensor, created_utc);

CREATE TABLE IF NOT EXISTS session_calibrations (
    session_id     BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    calibration_id BIGINT NOT NULL REFERENCES calibrations (id) ON DELETE RESTRICT,
    PRIMARY KEY (session_id, calibration_id)
);
)sql";

// Schema 11 (issue 56): samples and the pyramid partitioned by the month
// of their session's start (docs/fleet.md, "Sizing a site"), so a month's
// indexes stay in memory, vacuum works on one month, and an old month is
// detached (`server maintain`) without touching the rest. A row says its
// month (the partition key must be a column of the row); the server checks
// it is its session's. The partitions live in the schema `months`, which
// neither role may use: read through the parent, where the policies are.
//
// A month's partitions are made by the owner: `server init` and `server
// maintain` make the coming months, and a station about to send a session
// of a month not made yet asks month_ready() first, in a transaction of its
// own (a partition attached inside the session's transaction would hold a
// lock on the sessions table, and every other station's sync would wait,
// until the session had been sent). Attaching a fresh table rather than
// CREATE … PARTITION OF: that takes the parent's every lock, attaching only
// one that readers and writers pass.
constexpr const char* kMonthTables = R"sql(
CREATE SCHEMA IF NOT EXISTS months;
REVOKE ALL ON SCHEMA months FROM PUBLIC;

-- The first day of the month of a stored start time, in UTC.
CREATE OR REPLACE FUNCTION session_month(started text) RETURNS date LANGUAGE sql STABLE AS
    $body$ SELECT date_trunc('month', started::timestamptz AT TIME ZONE 'UTC')::date $body$;

-- A store made before schema 11: its plain tables moved aside, then copied
-- into the partitioned ones below.
DO $$ BEGIN
    IF EXISTS (SELECT 1 FROM pg_class WHERE oid = to_regclass('public.chunks') AND relkind = 'r') THEN
        ALTER TABLE chunks RENAME TO chunks_before_months;
        ALTER INDEX chunks_pkey RENAME TO chunks_before_months_pkey;
    END IF;
    IF EXISTS (SELECT 1 FROM pg_class WHERE oid = to_regclass('public.lod') AND relkind = 'r') THEN
        ALTER TABLE lod RENAME TO lod_before_months;
        ALTER INDEX lod_pkey RENAME TO lod_before_months_pkey;
    END IF;
END $$;

CREATE TABLE IF NOT EXISTS chunks (
    session_id    BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    session_month DATE NOT NULL,
    first_index   BIGINT NOT NULL,
    first_time_s  DOUBLE PRECISION NOT NULL,
    count         INTEGER NOT NULL CHECK (count > 0),
    samples       BYTEA NOT NULL,
    PRIMARY KEY (session_id, first_index, session_month)
) PARTITION BY RANGE (session_month);

CREATE TABLE IF NOT EXISTS lod (
    session_id    BIGINT NOT NULL REFERENCES sessions (id) ON DELETE CASCADE,
    session_month DATE NOT NULL,
    channel       INTEGER NOT NULL,
    level         INTEGER NOT NULL,
    first_bucket  BIGINT NOT NULL,
    count         INTEGER NOT NULL CHECK (count > 0),
    buckets       BYTEA NOT NULL,
    PRIMARY KEY (session_id, channel, level, first_bucket, session_month)
) PARTITION BY RANGE (session_month);

-- Samples and pyramid rows are binary32s, which pglz does not shrink:
-- stored out of line uncompressed, nothing is spent trying. (Each month's
-- table takes it from its parent.)
ALTER TABLE chunks ALTER COLUMN samples SET STORAGE EXTERNAL;
ALTER TABLE lod ALTER COLUMN buckets SET STORAGE EXTERNAL;

-- The months detached by `server maintain --detach-before`: their tables
-- stay in the schema months, out of the store, until the owner archives
-- and drops them or attaches them again.
CREATE TABLE IF NOT EXISTS detached_months (
    month        DATE PRIMARY KEY,
    detached_utc TEXT NOT NULL
);

-- Makes month's partitions of chunks and lod where missing. The owner's.
CREATE OR REPLACE FUNCTION make_month(month date) RETURNS void LANGUAGE plpgsql SET search_path = public AS $body$
DECLARE
    t text;
BEGIN
    PERFORM pg_advisory_xact_lock(7428);  -- one maker at a time: two stations may ask at once
    FOREACH t IN ARRAY ARRAY['chunks', 'lod'] LOOP
        IF to_regclass(format('months.%I', t || '_' || to_char(month, 'YYYY_MM'))) IS NULL THEN
            EXECUTE format('CREATE TABLE months.%I (LIKE %I INCLUDING DEFAULTS INCLUDING CONSTRAINTS INCLUDING STORAGE)',
                           t || '_' || to_char(month, 'YYYY_MM'), t);
            EXECUTE format('ALTER TABLE %I ATTACH PARTITION months.%I FOR VALUES FROM (%L) TO (%L)', t,
                           t || '_' || to_char(month, 'YYYY_MM'), month, (month + interval '1 month')::date);
        END IF;
    END LOOP;
END
$body$;
REVOKE ALL ON FUNCTION make_month(date) FROM PUBLIC;

DO $$ DECLARE m date; BEGIN
    IF to_regclass('public.chunks_before_months') IS NOT NULL THEN
        FOR m IN SELECT DISTINCT session_month(s.started_utc) FROM sessions s
                  WHERE EXISTS (SELECT 1 FROM chunks_before_months c WHERE c.session_id = s.id)
                     OR EXISTS (SELECT 1 FROM lod_before_months l WHERE l.session_id = s.id) LOOP
            PERFORM make_month(m);
        END LOOP;
        INSERT INTO chunks (session_id, session_month, first_index, first_time_s, count, samples)
            SELECT c.session_id, session_month(s.started_utc), c.first_index, c.first_time_s, c.count, c.samples
              FROM chunks_before_months c JOIN sessions s ON s.id = c.session_id;
        INSERT INTO lod (session_id, session_month, channel, level, first_bucket, count, buckets)
            SELECT l.session_id, session_month(s.started_utc), l.channel, l.level, l.first_bucket, l.count, l.buckets
              FROM lod_before_months l JOIN sessions s ON s.id = l.session_id;
        DROP TABLE chunks_before_months, lod_before_months;
    END IF;
END $$;

-- This month and the next two, as `server maintain` keeps them.
SELECT make_month((date_trunc('month', now() AT TIME ZONE 'UTC') + make_interval(months => k))::date)
  FROM generate_series(0, 2) k;

-- A station's question before it sends a session started at `started`:
-- the month its rows go in, made if missing. The start is judged as the
-- session's own will be (claimed_time: no later than the server's clock);
-- no month before 2000 is made for anyone (a station cannot fill the
-- schema with centuries of empty tables), nor one detached.
CREATE OR REPLACE FUNCTION month_ready(started text) RETURNS date LANGUAGE plpgsql SECURITY DEFINER
SET search_path = public AS $body$
DECLARE
    kept date;
    detached text;
BEGIN
    PERFORM claimed_time(started, 'its start');
    kept := session_month(started);
    IF kept < '2000-01-01' THEN
        RAISE EXCEPTION 'its start % is before 2000; the central store keeps no such month', started
            USING ERRCODE = 'check_violation';
    END IF;
    SELECT detached_utc INTO detached FROM detached_months WHERE month = kept;
    IF detached IS NOT NULL THEN
        RAISE EXCEPTION 'the month % was detached from the central store on %; its owner attaches it again '
            '(server maintain --attach %) before sessions of that month can be sent; this one waits',
            to_char(kept, 'YYYY-MM'),
            detached, to_char(kept, 'YYYY-MM') USING ERRCODE = 'object_not_in_prerequisite_state';
    END IF;
    PERFORM make_month(kept);
    RETURN kept;
END
$body$;
REVOKE ALL ON FUNCTION month_ready(text) FROM PUBLIC;
GRANT EXECUTE ON FUNCTION month_ready(text) TO tactiscope_station;
)sql";

// Schema 11 (issue 56): what a list shows of a session beyond its own
// columns (its sample count, live events, rate and parts), kept in the
// session's row by the server as the session is made complete, after
// which none of it changes. A list of 5 000 sessions then reads 5 000 rows,
// where asking each row's chunks, gaps, events, channels and parts (each
// also under its own row-level policy) took 110–170 ms for a filter whose
// sessions lie scattered over the table. Sessions made complete before,
// or written by the owner, are filled in here; readers ask the rows
// themselves where a column is still empty.
constexpr const char* kListedCounts = R"sql(
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS listed_samples BIGINT;
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS listed_events BIGINT;
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS listed_rate_hz DOUBLE PRECISION;
ALTER TABLE sessions ADD COLUMN IF NOT EXISTS listed_parts BIGINT;

-- A session's sample count (the end of its last chunk or gap), its live
-- events and its parts' (a session of several devices counts theirs), the
-- rate of its first channel, and its whole parts. CentralStore's list asks
-- the same of a row without them (kSummaryQuery): change both together.
CREATE OR REPLACE FUNCTION listed_counts(session bigint, started text, OUT samples bigint, OUT events bigint,
                                         OUT rate_hz double precision, OUT parts bigint)
LANGUAGE sql STABLE SET search_path = public AS $body$
SELECT greatest(coalesce((SELECT first_index + count FROM chunks WHERE session_id = session
                            AND session_month = session_month(started) ORDER BY first_index DESC LIMIT 1), 0),
                coalesce((SELECT first_index + count FROM gaps WHERE session_id = session
                           ORDER BY first_index DESC LIMIT 1), 0)),
       (SELECT count(*) FROM events WHERE session_id = session AND analysis = 'live')
         + (SELECT count(*) FROM events e JOIN sessions p ON e.session_id = p.id
             WHERE p.parent_id = session AND e.analysis = 'live'),
       coalesce((SELECT sample_rate_hz FROM channels WHERE session_id = session AND position = 0), 0),
       (SELECT count(*) FROM sessions p WHERE p.parent_id = session AND p.complete)
$body$;
REVOKE ALL ON FUNCTION listed_counts(bigint, text) FROM PUBLIC;

UPDATE sessions s SET (listed_samples, listed_events, listed_rate_hz, listed_parts) =
       (SELECT c.samples, c.events, c.rate_hz, c.parts FROM listed_counts(s.id, s.started_utc) c)
 WHERE complete AND listed_samples IS NULL;
)sql";

// Schema 5: bounds on every number a reader sizes something by, so no
// station can add a row that hangs or exhausts a reviewer's reader (the
// readers check each session's layout too: SessionBounds). NOT VALID: they
// hold for every row added from now on; rows already there are the
// readers' to judge. Times must be finite: PostgreSQL orders NaN above
// Infinity, so "< 'Infinity'" refuses both. 2⁵⁰ samples is 3 500 years at
// 10 kHz; a chunk holds at most kMostChunkSamples (2²⁶) samples.
constexpr const char* kBounds = R"sql(
ALTER TABLE channels DROP CONSTRAINT IF EXISTS channels_bounds;
ALTER TABLE channels ADD CONSTRAINT channels_bounds
    CHECK (position >= 0 AND position < 100000 AND sample_rate_hz > 0 AND sample_rate_hz <= 1e9) NOT VALID;
ALTER TABLE chunks DROP CONSTRAINT IF EXISTS chunks_bounds;
ALTER TABLE chunks ADD CONSTRAINT chunks_bounds
    CHECK (first_index >= 0 AND first_index <= 1125899906842624 AND count <= 67108864
           AND first_time_s > '-Infinity' AND first_time_s < 'Infinity') NOT VALID;
ALTER TABLE gaps DROP CONSTRAINT IF EXISTS gaps_bounds;
ALTER TABLE gaps ADD CONSTRAINT gaps_bounds
    CHECK (first_index >= 0 AND count <= 1125899906842624 AND first_index + count <= 1125899906842624) NOT VALID;
ALTER TABLE lod DROP CONSTRAINT IF EXISTS lod_bounds;
ALTER TABLE lod ADD CONSTRAINT lod_bounds
    CHECK (channel >= 0 AND level >= 0 AND level < 64 AND first_bucket >= 0
           AND first_bucket <= 1125899906842624 AND octet_length(buckets) = 8 * count::bigint) NOT VALID;
ALTER TABLE zeros DROP CONSTRAINT IF EXISTS zeros_bounds;
ALTER TABLE zeros ADD CONSTRAINT zeros_bounds CHECK (first_index >= 0) NOT VALID;
ALTER TABLE events DROP CONSTRAINT IF EXISTS events_bounds;
ALTER TABLE events ADD CONSTRAINT events_bounds
    CHECK (start_s > '-Infinity' AND start_s < 'Infinity' AND end_s < 'Infinity') NOT VALID;
ALTER TABLE readings DROP CONSTRAINT IF EXISTS readings_bounds;
ALTER TABLE readings ADD CONSTRAINT readings_bounds
    CHECK (start_s > '-Infinity' AND start_s < 'Infinity' AND end_s < 'Infinity') NOT VALID;
ALTER TABLE annotations DROP CONSTRAINT IF EXISTS annotations_bounds;
ALTER TABLE annotations ADD CONSTRAINT annotations_bounds
    CHECK (time_s > '-Infinity' AND time_s < 'Infinity') NOT VALID;
)sql";

// Schema 10 (issue 56): every list's question has an index path, at a
// year's scale. A list reads whole sessions that are no part, newest first
// (by start, then id): each filter's index holds only those, its column
// first, then that order, so a filtered page is one index range read to
// its limit.
//
// The text search is a trigram index over the searched text
// (kSessionSearchText; pg_trgm ships with Debian's PostgreSQL and is
// trusted: the database's owner creates it). A reviewer's or a station's
// query cannot use it: under row-level security the server evaluates a
// qual that is not leakproof, as ILIKE is not, only after the policy's,
// never as an index condition. So the search is a function run as the
// owner, who reads through the index, which returns only the sessions
// the caller may see (the policies' own rule: a station its own, a
// reviewer or the owner every whole one); the caller's query joins them
// under its own policies still, each by its id (ROWS 10: a search finds
// few, so the planner looks them up rather than reading every session).
std::string listingIndexes()
{
    const std::string listed = " WHERE complete AND parent_id IS NULL;\n";
    std::string sql = "CREATE INDEX IF NOT EXISTS sessions_listed ON sessions (started_utc DESC, id DESC)" + listed;
    for (const char* column : {"station", "subject", "operator", "mode", "status", "verdict"})
        sql += std::string("CREATE INDEX IF NOT EXISTS sessions_listed_by_") + column + " ON sessions (" + column +
               ", started_utc DESC, id DESC)" + listed;
    const std::string text = kSessionSearchText;
    sql += "CREATE EXTENSION IF NOT EXISTS pg_trgm;\n";
    sql +=
        "CREATE INDEX IF NOT EXISTS sessions_listed_by_text ON sessions USING gin (" + text + " gin_trgm_ops)" + listed;
    sql += "CREATE OR REPLACE FUNCTION sessions_with_text(pattern text) RETURNS SETOF bigint LANGUAGE sql STABLE "
           "SECURITY DEFINER SET search_path = public ROWS 10 AS $body$\n"
           "SELECT id FROM sessions WHERE complete AND parent_id IS NULL AND " +
           text +
           " ILIKE pattern ESCAPE '\\'\n"
           "   AND (station = session_user OR pg_has_role(session_user, 'tactiscope_reviewer', 'MEMBER')\n"
           "        OR pg_has_role(session_user, (SELECT relowner FROM pg_class WHERE oid = 'sessions'::regclass), "
           "'MEMBER'))\n"
           "$body$;\n"
           "REVOKE ALL ON FUNCTION sessions_with_text(text) FROM PUBLIC;\n"
           "GRANT EXECUTE ON FUNCTION sessions_with_text(text) TO tactiscope_station, tactiscope_reviewer;\n";
    return sql;
}

// Rights and row-level security (docs/fleet.md, "Roles and rights"). A
// station reads and adds its own rows, in its own name; a reviewer reads
// every finished session and adds notes and reviewer verdicts in their own
// name; only the owner (who bypasses RLS) changes or deletes. Nobody sets
// an identity value (INSERT is granted on every column but the id, so
// OVERRIDING SYSTEM VALUE is refused), an added_by (its default is the
// login; a station's rows must name it as their station anyway), or a
// session's verdict: the server derives it from the verdict trail. A
// session is added unfinished; a station's only update is the sync's last
// step, its own unfinished session made complete (with its checksum), after
// which nothing more of it may be added but notes and decisions. Rights
// are revoked and given again, policies dropped and made again, so an
// upgrade (`server init`) changes them.
constexpr const char* kRights = R"sql(
REVOKE ALL ON ALL TABLES IN SCHEMA public FROM tactiscope_station, tactiscope_reviewer;
GRANT USAGE ON SCHEMA public TO tactiscope_station, tactiscope_reviewer;
GRANT SELECT ON ALL TABLES IN SCHEMA public TO tactiscope_station, tactiscope_reviewer;
DO $rights$
DECLARE
    t text;
    columns text;
BEGIN
    FOREACH t IN ARRAY ARRAY['sessions', 'channels', 'chunks', 'gaps', 'lod', 'events', 'readings', 'annotations',
                             'verdicts', 'zeros', 'calibrations', 'session_calibrations'] LOOP
        SELECT string_agg(quote_ident(column_name), ', ') INTO columns FROM information_schema.columns
         WHERE table_schema = 'public' AND table_name = t
           AND column_name NOT IN ('id', 'added_by')
           AND NOT (t = 'sessions' AND (column_name IN ('verdict', 'complete', 'checksum')
                                        OR column_name LIKE 'listed\_%'));
        EXECUTE format('GRANT INSERT (%s) ON %I TO tactiscope_station', columns, t);
        IF t IN ('annotations', 'verdicts') THEN
            EXECUTE format('GRANT INSERT (%s) ON %I TO tactiscope_reviewer', columns, t);
        END IF;
    END LOOP;
END
$rights$;
GRANT UPDATE (complete, checksum) ON sessions TO tactiscope_station;

DROP POLICY IF EXISTS reviewer_verdict ON sessions;
DROP POLICY IF EXISTS station_completes ON sessions;
CREATE POLICY station_completes ON sessions AS RESTRICTIVE FOR UPDATE TO tactiscope_station
    USING (NOT complete) WITH CHECK (complete);
)sql";

// A row trigger `name` on `table`, its PL/pgSQL `body` run as the owner
// (whatever the inserting role may see or do) and callable by no client.
std::string serverTrigger(const std::string& name, const std::string& when, const std::string& table,
                          const std::string& body)
{
    return "CREATE OR REPLACE FUNCTION " + name +
           "() RETURNS trigger LANGUAGE plpgsql SECURITY DEFINER SET search_path = public AS $body$\n" + body +
           "\n$body$;\nREVOKE ALL ON FUNCTION " + name + "() FROM PUBLIC;\nDROP TRIGGER IF EXISTS " + name + " ON " +
           table + ";\nCREATE TRIGGER " + name + " " + when + " ON " + table + " FOR EACH ROW EXECUTE FUNCTION " +
           name + "();\n";
}

// A chunk holds count samples of each of its session's channels, 4 bytes
// each (the sync sends the channel rows first), and lies in its session's
// month: counted as the owner, the channels whatever the inserting role
// may see.
constexpr const char* kChunkFitsChannels = R"sql(
DECLARE
    channel_count bigint;
BEGIN
    SELECT count(*) INTO channel_count FROM channels WHERE session_id = NEW.session_id;
    IF octet_length(NEW.samples) <> NEW.count::bigint * channel_count * 4 THEN
        RAISE EXCEPTION 'a chunk of % samples of % channels holds % bytes, not %', NEW.count, channel_count,
            NEW.count::bigint * channel_count * 4, octet_length(NEW.samples) USING ERRCODE = 'check_violation';
    END IF;
    PERFORM in_its_month(NEW.session_id, NEW.session_month);
    RETURN NEW;
END)sql";

// A pyramid row lies in its session's month.
constexpr const char* kLodInItsMonth = R"sql(
BEGIN
    PERFORM in_its_month(NEW.session_id, NEW.session_month);
    RETURN NEW;
END)sql";

// Refuses a row of `session` said to lie in another month than its
// session's start (a row in the wrong month would be detached, or kept,
// with another month's sessions).
constexpr const char* kInItsMonth = R"sql(
CREATE OR REPLACE FUNCTION in_its_month(session bigint, month date) RETURNS void LANGUAGE plpgsql
SET search_path = public AS $body$
DECLARE
    started text;
BEGIN
    SELECT started_utc INTO started FROM sessions WHERE id = session;
    IF started IS NOT NULL AND session_month(started) IS DISTINCT FROM month THEN
        RAISE EXCEPTION 'a row of a session started % belongs to the month %, not %', started,
            to_char(session_month(started), 'YYYY-MM'), coalesce(to_char(month, 'YYYY-MM'), 'none')
            USING ERRCODE = 'check_violation';
    END IF;
END
$body$;
REVOKE ALL ON FUNCTION in_its_month(bigint, date) FROM PUBLIC;
)sql";

// A device's part joins a session of its own station's that is still being
// sent, and a session of one level: no station hangs a part on another's
// session (its reviewers would read it as that station's), adds one to a
// finished session, or nests parts.
constexpr const char* kPartOfOwnSession = R"sql(
BEGIN
    IF NEW.parent_id IS NOT NULL AND NOT EXISTS (
            SELECT 1 FROM sessions p WHERE p.id = NEW.parent_id AND p.station = NEW.station AND NOT p.complete
               AND p.parent_id IS NULL) THEN
        RAISE EXCEPTION 'a device''s part belongs to a session of its own station still being sent'
            USING ERRCODE = 'check_violation';
    END IF;
    RETURN NEW;
END)sql";

// Schema 9: the server judges what a station claims.
//
// A time a station claims (made at the station, perhaps long before it is
// sent) is judged as it arrives: a UTC time in the stored form, a real
// date, and not later than the server's clock by more than a skew between
// two clocks kept by NTP; never rewritten, so the sync still finds what it
// sent. Made once, called only by the server's own triggers.
constexpr const char* kClaimedTime = R"sql(
-- The server's clock in the stored form, for what is decided here.
CREATE OR REPLACE FUNCTION server_utc() RETURNS text LANGUAGE sql AS
    $body$ SELECT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"') $body$;
REVOKE ALL ON FUNCTION server_utc() FROM PUBLIC;
CREATE OR REPLACE FUNCTION claimed_time(claimed text, what text) RETURNS timestamptz
LANGUAGE plpgsql SET search_path = public AS $body$
DECLARE
    quoted text := CASE WHEN length(claimed) > 40 THEN left(claimed, 40) || '... (' || length(claimed) || ' characters)'
                        ELSE claimed END;
    t timestamptz;
BEGIN
    IF claimed IS NULL OR claimed !~ '^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}(\.[0-9]{1,9})?Z$' THEN
        RAISE EXCEPTION '% ''%'' is not a UTC time such as 2026-11-28T14:20:28.123Z', what, coalesce(quoted, 'null')
            USING ERRCODE = 'check_violation';
    END IF;
    BEGIN
        t := claimed::timestamptz;
    EXCEPTION WHEN others THEN
        RAISE EXCEPTION '% ''%'' is not a date', what, quoted USING ERRCODE = 'check_violation';
    END;
    IF t > clock_timestamp() + interval '5 minutes' THEN
        RAISE EXCEPTION '% % is later than the central store''s clock (%): the station''s clock is ahead of it',
            what, quoted, server_utc()
            USING ERRCODE = 'check_violation';
    END IF;
    RETURN t;
END
$body$;
REVOKE ALL ON FUNCTION claimed_time(text, text) FROM PUBLIC;
)sql";

// The times a station claims for its session.
constexpr const char* kSessionTimesJudged = R"sql(
DECLARE
    started timestamptz := claimed_time(NEW.started_utc, 'its start');
BEGIN
    IF NEW.ended_utc IS NOT NULL AND claimed_time(NEW.ended_utc, 'its end') < started THEN
        RAISE EXCEPTION 'its end % is before its start %', NEW.ended_utc, NEW.started_utc
            USING ERRCODE = 'check_violation';
    END IF;
    RETURN NEW;
END)sql";

// A decision or a note made here is dated by the server's clock; one a
// station sends was made there, and its claimed times are judged. Were a
// station to date a decision as it liked, it could set one "9999-12-31"
// that outranks every reviewer's (the trail's latest decision is the
// session's verdict).
constexpr const char* kVerdictTimeJudged = R"sql(
BEGIN
    IF NEW.role = 'reviewer' THEN
        NEW.decided_utc := server_utc();
    ELSE
        PERFORM claimed_time(NEW.decided_utc, 'the decision''s time');
    END IF;
    RETURN NEW;
END)sql";

constexpr const char* kNoteTimesJudged = R"sql(
BEGIN
    IF pg_has_role(NEW.added_by, 'tactiscope_station', 'MEMBER') THEN
        PERFORM claimed_time(NEW.created_utc, 'the note''s time');
        PERFORM claimed_time(NEW.modified_utc, 'the note''s change time');
    ELSE
        NEW.created_utc := server_utc();
        NEW.modified_utc := NEW.created_utc;
    END IF;
    RETURN NEW;
END)sql";

// A session is complete once what arrived is what the station holds: the
// server computes the checksum the station claims (of its chunks, or for
// a session of several devices of its parts, each complete first, the
// same lines CentralSync's sessionChecksum builds) and refuses a mismatch.
// Before, a station could mark a session complete over made-up samples, or
// a session before its parts (reviewers then met "the store is damaged").
constexpr const char* kCompleteWhenWhole = R"sql(
DECLARE
    arrived text;
    unfinished bigint;
BEGIN
    IF NOT NEW.complete OR OLD.complete THEN
        RETURN NEW;
    END IF;
    IF EXISTS (SELECT 1 FROM sessions WHERE parent_id = NEW.id) THEN
        SELECT count(*) INTO unfinished FROM sessions WHERE parent_id = NEW.id AND NOT complete;
        IF unfinished > 0 THEN
            RAISE EXCEPTION 'a session of several devices is complete only after its parts: % of them not yet',
                unfinished USING ERRCODE = 'check_violation';
        END IF;
        SELECT md5(string_agg(device_name || ' ' || checksum || E'\n', '' ORDER BY id)) INTO arrived
          FROM sessions WHERE parent_id = NEW.id;
    ELSE
        SELECT md5(coalesce(string_agg(first_index || ':' || count || ':' || md5(samples), E'\n'
                                       ORDER BY first_index), '')) INTO arrived
          FROM chunks WHERE session_id = NEW.id;
    END IF;
    IF arrived IS DISTINCT FROM NEW.checksum THEN
        RAISE EXCEPTION 'its samples arrived damaged (checksum %, sent %); nothing of it was kept', arrived,
            left(NEW.checksum, 40) USING ERRCODE = 'check_violation';
    END IF;
    SELECT c.samples, c.events, c.rate_hz, c.parts INTO NEW.listed_samples, NEW.listed_events, NEW.listed_rate_hz,
           NEW.listed_parts FROM listed_counts(NEW.id, NEW.started_utc) c;
    RETURN NEW;
END)sql";

// The session's verdict is the latest decision of its trail, set by the
// server as each decision arrives.
constexpr const char* kVerdictFromTrail = R"sql(
BEGIN
    UPDATE sessions SET verdict = (SELECT v.verdict FROM verdicts v WHERE v.session_id = NEW.session_id
                                   ORDER BY v.decided_utc DESC, v.id DESC LIMIT 1)
     WHERE id = NEW.session_id;
    RETURN NULL;
END)sql";

// The tables whose rows belong to a session: a station's rows are those of
// its own sessions; a reviewer reads those of finished sessions.
constexpr const char* kSessionTables[] = {"channels",    "chunks",   "gaps",  "lod",
                                          "events",      "readings", "zeros", "session_calibrations",
                                          "annotations", "verdicts"};

// Row-level security on `table`: a station's rows are those where `own`
// holds, a reviewer reads those where `readable` holds.
std::string policies(const std::string& table, const std::string& own, const std::string& readable)
{
    std::string sql = "ALTER TABLE " + table + " ENABLE ROW LEVEL SECURITY;\n";
    sql += "DROP POLICY IF EXISTS station_own ON " + table + ";\n";
    sql += "CREATE POLICY station_own ON " + table + " TO tactiscope_station USING (" + own + ") WITH CHECK (" + own +
           ");\n";
    sql += "DROP POLICY IF EXISTS reviewer_reads ON " + table + ";\n";
    sql +=
        "CREATE POLICY reviewer_reads ON " + table + " FOR SELECT TO tactiscope_reviewer USING (" + readable + ");\n";
    return sql;
}

std::string sessionTablePolicies(const std::string& table)
{
    const std::string own = "EXISTS (SELECT 1 FROM sessions s WHERE s.id = session_id AND s.station = current_user)";
    const std::string finished = "EXISTS (SELECT 1 FROM sessions s WHERE s.id = session_id AND s.complete)";
    std::string sql = policies(table, own, finished);
    if (table != "annotations" && table != "verdicts") {
        // What a session holds is added while it is sent, never after: a
        // finished session's samples, gaps and records stay as reviewed.
        const std::string sending = "EXISTS (SELECT 1 FROM sessions s WHERE s.id = session_id AND NOT s.complete)";
        sql += "DROP POLICY IF EXISTS station_adds_while_sending ON " + table + ";\n";
        sql += "CREATE POLICY station_adds_while_sending ON " + table +
               " AS RESTRICTIVE FOR INSERT TO tactiscope_station WITH CHECK (" + sending + ");\n";
    }
    if (table == "annotations" || table == "verdicts") {
        // A station's verdicts are the automatic one and its operators'; a
        // reviewer's are reviewer verdicts (decided_by names the person;
        // added_by, the login, cannot be set).
        const std::string reviewerRole = table == "verdicts" ? " AND role = 'reviewer'" : "";
        sql += "DROP POLICY IF EXISTS reviewer_adds ON " + table + ";\n";
        sql += "CREATE POLICY reviewer_adds ON " + table + " FOR INSERT TO tactiscope_reviewer WITH CHECK (" +
               finished + " AND added_by = current_user" + reviewerRole + ");\n";
        if (table == "verdicts") {
            sql += "DROP POLICY IF EXISTS station_decides ON verdicts;\n";
            sql += "CREATE POLICY station_decides ON verdicts AS RESTRICTIVE FOR INSERT TO tactiscope_station "
                   "WITH CHECK (role IN ('automatic', 'operator') AND added_by = current_user);\n";
        }
    }
    return sql;
}

}  // namespace

void initCentralStore(PgConnection& connection)
{
    // An upgrade may move a year of samples into their months, or fill a
    // year of sessions' listed counts: minutes, not the product's minute.
    connection.allowLongStatements();
    // One transaction: a store half made is never left behind; two stations
    // running it at once wait for each other on the lock.
    std::string script = "BEGIN;\nSELECT pg_advisory_xact_lock(7426);\n";
    script += kSchema;
    script += kMonthTables;
    script += kListedCounts;
    script += kBounds;
    script += listingIndexes();
    script += kInItsMonth;
    script += serverTrigger("chunk_fits_channels", "BEFORE INSERT", "chunks", kChunkFitsChannels);
    script += serverTrigger("lod_in_its_month", "BEFORE INSERT", "lod", kLodInItsMonth);
    script += serverTrigger("part_of_own_session", "BEFORE INSERT", "sessions", kPartOfOwnSession);
    script += kClaimedTime;
    script += serverTrigger("session_times_judged", "BEFORE INSERT", "sessions", kSessionTimesJudged);
    script += serverTrigger("complete_when_whole", "BEFORE UPDATE", "sessions", kCompleteWhenWhole);
    script += kRights;
    script += serverTrigger("verdict_time_judged", "BEFORE INSERT", "verdicts", kVerdictTimeJudged);
    script += serverTrigger("note_times_judged", "BEFORE INSERT", "annotations", kNoteTimesJudged);
    script += serverTrigger("verdict_from_trail", "AFTER INSERT", "verdicts", kVerdictFromTrail);
    script += policies("sessions", "station = current_user", "complete");
    script += policies("calibrations", "station = current_user", "true");
    for (const char* table : kSessionTables) script += sessionTablePolicies(table);
    script += "DELETE FROM schema_version;\nINSERT INTO schema_version VALUES (" +
              std::to_string(kCentralSchemaVersion) + ");\nCOMMIT;\n";
    connection.run(script);
}

}  // namespace tactiscope::core::storage::central
