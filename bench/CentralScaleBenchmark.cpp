// The central store at a year's scale (issue 56), as a reviewer asks it: a
// PostgreSQL server started here grows, by SQL, a clinic's year (20 carts,
// 1.2 M palpations of 3 ch × 1 kHz × 60 s) and a press shop's month (100
// stations, 3 M panel scans of 2 ch × 500 Hz × 30 s), each beside a
// baseline of a hundredth of it in the same run; then times, as a
// reviewer's login (row-level security on), what `sessions list`, `show`,
// `export` and `report` and the session browser ask of it: the median of
// five warm runs, and its ratio to the baseline (a question whose time does
// not grow with the store reads ≈ 1).
//
// What is grown is what those questions read, in the shape a sync writes:
// every session row (its station, subject, operator, site, notes, status,
// verdict), its channel rows, its chunk rows cut as the sync cuts them
// (4 096 instants) in its month's table, and a defect event where the
// verdict says so, and the counts a list shows kept in the session's row
// (as the server keeps them when a sync completes it). A chunk's samples are empty (a clinic's year of samples
// is 0.9 TB): no question here reads them but those of two sessions sent
// whole by a real sync, the newest ("last") and one in the middle of the
// span (asked by its uuid), whose samples, pyramid and records are real.
// Run: tactiscope_central_scale_bench [FRACTION] (default 1: full size).
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/CentralStore.h"
#include "core/storage/central/CentralSync.h"
#include "support/PostgresServer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <regex>
#include <set>
#include <unistd.h>

namespace {

using namespace tactiscope;
using core::storage::SessionFilter;
using core::storage::SessionStore;
using core::storage::central::CentralStore;
using core::storage::central::PgConnection;
namespace fs = std::filesystem;

struct Shape {
    std::string name;
    std::string station;  // prefix of the station names
    int stations;
    long long sessions;
    core::Mode mode;
    int channels;
    double rate_hz;
    int seconds;
    std::string from;       // the span's first day
    std::string nextMonth;  // the first day of the month after the span's first
    int days;
};

const Shape kClinic{"clinic year", "cart-",      20, 1200000, core::Mode::Palpation, 3, 1000.0, 60,
                    "2025-12-01",  "2026-01-01", 365};
const Shape kPress{"press month", "press-",     100, 3000000, core::Mode::PanelScan, 2, 500.0, 30,
                   "2026-10-01",  "2026-11-01", 31};

double since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void say(const std::string& line)
{
    std::cerr << line << std::endl;
}

// A station's store holding one real session of the shape, started at `startedUtc`.
std::string realSession(const fs::path& folder, const Shape& shape, const std::string& name,
                        const std::string& startedUtc)
{
    const std::string path = (folder / (name + ".tactiscope")).string();
    SessionStore store(path);
    std::vector<core::ChannelDescriptor> channels;
    for (int c = 0; c < shape.channels; ++c)
        channels.push_back({"ch" + std::to_string(c), "N", core::ChannelKind::Force});
    core::storage::SessionMetadata m;
    m.mode = shape.mode;
    m.subject = name;
    m.operatorName = "bench";
    const auto id = store.beginSession(m, channels, shape.rate_hz);
    const auto instants = static_cast<std::uint64_t>(shape.seconds * shape.rate_hz);
    const auto perCommit = static_cast<std::size_t>(shape.rate_hz / 4);  // the recorder's 250 ms
    for (std::uint64_t first = 0; first < instants; first += perCommit) {
        core::SampleBlock block(static_cast<std::size_t>(shape.channels), perCommit,
                                static_cast<double>(first) / shape.rate_hz, 1.0 / shape.rate_hz, first);
        for (int c = 0; c < shape.channels; ++c)
            for (std::size_t s = 0; s < perCommit; ++s)
                block.channel(static_cast<std::size_t>(c))[s] = std::sin(1e-2 * static_cast<double>(first + s) + c);
        store.appendBlocks(id, std::vector{block});
    }
    store.endSession(id, core::SessionStatus::Complete);
    auto update = store.database().prepare("UPDATE sessions SET started_utc = ? WHERE id = ?");
    update.bind(1, startedUtc).bind(2, id).run();
    return path;
}

// Grows `count` sessions of `shape` into the store at `conninfo` (its owner).
void grow(const std::string& conninfo, const Shape& shape, long long count)
{
    PgConnection db(conninfo);
    db.run("SET maintenance_work_mem = '1GB'");
    const auto instants = static_cast<long long>(shape.seconds * shape.rate_hz);
    const long long chunks = (instants + 4095) / 4096;
    const std::string n = std::to_string(count), from = "'" + shape.from + "'::timestamp";
    // Sessions evenly over the span, in start order (as syncs add them).
    const std::string step = std::to_string(shape.days * 86400.0 / static_cast<double>(count));
    const std::string started = "(" + from + " + g * interval '" + step + " seconds')";
    const bool press = shape.mode == core::Mode::PanelScan;
    const auto start = std::chrono::steady_clock::now();
    db.run("SELECT make_month(m::date) FROM generate_series(" + from + ", " + from + " + interval '" +
           std::to_string(shape.days) + " days', interval '1 month') m");
    // The listing's indexes made after the rows, as `server init` makes
    // them (far faster than row by row); the server's checks off for the
    // owner's bulk load (session_replication_role), as for a restore.
    for (const char* index :
         {"sessions_listed", "sessions_listed_by_station", "sessions_listed_by_subject", "sessions_listed_by_operator",
          "sessions_listed_by_mode", "sessions_listed_by_status", "sessions_listed_by_verdict",
          "sessions_listed_by_text", "sessions_started", "sessions_by_station"})
        db.run(std::string("DROP INDEX IF EXISTS ") + index);
    db.run("SET session_replication_role = replica");
    db.run(
        "INSERT INTO sessions (uuid, station, complete, mode, subject, operator, site, notes, started_utc, ended_utc, "
        "status, verdict, device_model, device_serial, device_firmware, app_version, station_id, listed_samples, "
        "listed_events, listed_rate_hz, listed_parts) "
        "SELECT md5('" +
        shape.name + "' || g), '" + shape.station + "' || lpad((g % " + std::to_string(shape.stations) +
        " + 1)::text, 3, '0'), true, '" + std::string(core::toString(shape.mode)) + "', " +
        (press ? "'panel-' || g" : "'phantom-' || (g::bigint * 7919 % 4000)") + ", " +
        (press ? "'op-' || (g % 300)" : "'nurse-' || (g % 40)") + ", " +
        (press ? "'line ' || (g % 10)"
               : "(ARRAY['left upper', 'left lower', 'right upper', 'right lower'])[g % 4 + 1]") +
        ", CASE WHEN g % 20 = 0 THEN 'recheck after service ' || g ELSE '' END, "
        "to_char(" +
        started + ", 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), to_char(" + started + " + interval '" +
        std::to_string(shape.seconds) +
        " seconds', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), "
        "CASE WHEN g % 400 = 0 THEN 'interrupted' ELSE 'complete' END, " +
        (press ? "CASE WHEN g % 40 = 0 THEN 'defects found' ELSE 'pass' END" : "''") + ", 'TS-2', 'SN-' || (g % " +
        std::to_string(shape.stations) + "), '1.4', '0.1.0', g, " + std::to_string(instants) + ", " +
        (press ? "CASE WHEN g % 40 = 0 THEN 1 ELSE 0 END" : "0") + ", " + std::to_string(shape.rate_hz) +
        ", 0 FROM generate_series(1, " + n + ") g");
    say("  sessions: " + std::to_string(since(start) / 1000) + " s");
    db.run("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) "
           "SELECT s.id, p, 'ch' || p, 'N', 'force', " +
           std::to_string(shape.rate_hz) + ", '' FROM sessions s, generate_series(0, " +
           std::to_string(shape.channels - 1) + ") p WHERE s.app_version = '0.1.0' AND s.device_model = 'TS-2'");
    say("  channels: " + std::to_string(since(start) / 1000) + " s");
    db.run("INSERT INTO chunks (session_id, session_month, first_index, first_time_s, count, samples) "
           "SELECT s.id, session_month(s.started_utc), k * 4096, k * 4096 / " +
           std::to_string(shape.rate_hz) + ", least(4096, " + std::to_string(instants) +
           " - k * 4096), ''::bytea FROM sessions s, generate_series(0, " + std::to_string(chunks - 1) +
           ") k WHERE s.device_model = 'TS-2'");
    say("  chunks: " + std::to_string(since(start) / 1000) + " s");
    db.run("INSERT INTO events (session_id, kind, start_s, end_s, direction) "
           "SELECT id, 'defect', 12.5, 12.6, 1 FROM sessions WHERE verdict = 'defects found'");
    db.run("SET session_replication_role = origin");
    core::storage::central::initCentralStore(db);  // the indexes again
    say("  indexes: " + std::to_string(since(start) / 1000) + " s");
    db.run("VACUUM ANALYZE");
    say("  vacuum: " + std::to_string(since(start) / 1000) + " s");
}

// The median of five runs after one to warm.
double medianMs(const std::function<void()>& ask)
{
    ask();
    std::vector<double> times;
    for (int i = 0; i < 5; ++i) {
        const auto start = std::chrono::steady_clock::now();
        ask();
        times.push_back(since(start));
    }
    std::ranges::sort(times);
    return times[2];
}

// The indexes a plan reads, by name.
std::string planShape(const std::string& plan)
{
    static const std::regex index("\"Index Name\": \"([^\"]+)\"");
    std::set<std::string> names;
    for (auto m = std::sregex_iterator(plan.begin(), plan.end(), index); m != std::sregex_iterator(); ++m)
        names.insert((*m)[1]);
    std::string shape;
    for (const std::string& name : names)
        if (name.rfind("sessions", 0) == 0) shape += (shape.empty() ? "" : ", ") + name;
    if (plan.find("sessions_with_text") != std::string::npos) shape += ", sessions_with_text()";
    static const std::regex scan("\"Node Type\": \"Seq Scan\",[^}]*?\"Relation Name\": \"([^\"]+)\"");
    std::set<std::string> scanned;
    for (auto m = std::sregex_iterator(plan.begin(), plan.end(), scan); m != std::sregex_iterator(); ++m)
        scanned.insert((*m)[1]);
    for (const std::string& table : scanned) shape += "; every row of " + table;
    return shape.empty() ? "—" : shape;
}

struct Question {
    std::string what;
    std::function<void(CentralStore&)> ask;
    std::optional<SessionFilter> listing;  // for its plan
};

// What `show` reads of a session; `samples` and `overview` add `export`'s
// and `report`'s reads.
void readSession(CentralStore& store, std::int64_t id, bool samples, bool overview)
{
    const auto summary = store.session(id);
    const auto channels = store.channels(id);
    store.gaps(id);
    store.events(id);
    store.readings(id);
    store.verdicts(id);
    store.annotations(id);
    const std::uint64_t count = store.sampleCount(id);
    if (samples) {
        std::vector<std::size_t> all(channels.size());
        for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
        std::vector<std::vector<double>> out;
        for (std::uint64_t first = 0; first < count; first += 65536)
            store.readChannels(id, all, first, std::min<std::uint64_t>(65536, count - first), out);
    }
    if (overview)
        for (std::size_t c = 0; c < channels.size(); ++c) store.overview(id, c, 0, count, 1920);
}

std::vector<Question> questions(const Shape& shape, const std::string& middleUuid)
{
    const auto list = [](SessionFilter f, std::size_t limit) {
        f.limit = limit;
        return f;
    };
    const auto filtered = [&](const std::string& what, SessionFilter f) {
        std::vector<Question> both;
        for (const std::size_t limit : {std::size_t{100}, std::size_t{5000}}) {
            const SessionFilter asked = list(f, limit);
            both.push_back(
                {(limit == 100 ? "list " : "browser ") + what, [asked](CentralStore& s) { s.sessions(asked); }, asked});
        }
        return both;
    };
    std::vector<Question> q;
    q.push_back({"show last", [](CentralStore& s) { readSession(s, *s.lastSession(), false, false); }, {}});
    q.push_back({"show by uuid",
                 [middleUuid](CentralStore& s) { readSession(s, *s.sessionWithUuid(middleUuid), false, false); },
                 {}});
    q.push_back({"export by uuid (every sample)",
                 [middleUuid](CentralStore& s) { readSession(s, *s.sessionWithUuid(middleUuid), true, false); },
                 {}});
    q.push_back({"report by uuid (overview of each channel)",
                 [middleUuid](CentralStore& s) { readSession(s, *s.sessionWithUuid(middleUuid), false, true); },
                 {}});
    SessionFilter f;
    for (auto& x : filtered("(no filter)", f)) q.push_back(x);
    f.station = shape.station + "007";
    for (auto& x : filtered("station", f)) q.push_back(x);
    f = {};
    // A day, the span's first month, and everything.
    f.startedFrom = shape.from.substr(0, 8) + "15T00:00:00.000Z";
    f.startedBefore = shape.from.substr(0, 8) + "16T00:00:00.000Z";
    for (auto& x : filtered("day", f)) q.push_back(x);
    f.startedFrom = shape.from + "T00:00:00.000Z";
    f.startedBefore = shape.nextMonth + "T00:00:00.000Z";
    for (auto& x : filtered("month", f)) q.push_back(x);
    f.startedFrom = "2000-01-01T00:00:00.000Z";
    f.startedBefore = "2100-01-01T00:00:00.000Z";
    for (auto& x : filtered("year", f)) q.push_back(x);
    f = {};
    f.subject = shape.mode == core::Mode::PanelScan ? "panel-1234567" : "phantom-1234";
    for (auto& x : filtered("subject", f)) q.push_back(x);
    f = {};
    f.operatorName = shape.mode == core::Mode::PanelScan ? "op-42" : "nurse-7";
    for (auto& x : filtered("operator", f)) q.push_back(x);
    f = {};
    f.verdict = core::Verdict::DefectsFound;
    for (auto& x : filtered("verdict", f)) q.push_back(x);
    f = {};
    f.mode = core::Mode::Capacitive;  // none of the store's
    for (auto& x : filtered("mode (none match)", f)) q.push_back(x);
    f = {};
    f.status = core::SessionStatus::Interrupted;
    for (auto& x : filtered("status", f)) q.push_back(x);
    f = {};
    f.text = "after service 12345";
    for (auto& x : filtered("text", f)) q.push_back(x);
    return q;
}

// A store of `count` sessions of `shape` in database `name`, with its two
// real sessions; returns the uuid of the middle one.
std::string makeStore(testing::PostgresServer& server, const fs::path& folder, const Shape& shape,
                      const std::string& name, long long count)
{
    PgConnection(server.conninfo()).run("CREATE DATABASE " + name);
    const std::string owner = server.conninfo(testing::PostgresServer::kOwner, name);
    {
        PgConnection db(owner);
        core::storage::central::initCentralStore(db);
    }
    say(shape.name + " (" + name + "): growing " + std::to_string(count) + " sessions");
    grow(owner, shape, count);
    // Sent whole by a real sync: one in the middle of the span, then the newest.
    const std::string middle =
        realSession(folder, shape, name + "-middle", shape.from.substr(0, 8) + "15T09:00:00.000Z");
    const std::string newest =
        realSession(folder, shape, name + "-newest", shape.from.substr(0, 8) + "20T09:00:00.000Z");
    CentralStore central(owner);
    for (const std::string& path : {middle, newest}) {
        SessionStore local(path, core::storage::Database::Access::ReadOnly);
        const auto start = std::chrono::steady_clock::now();
        const auto outcome = core::storage::central::syncToCentral(local, central, shape.station + "001");
        say("  sync of one session into it: " + std::to_string(since(start)) + " ms, " + std::to_string(outcome.sent) +
            " sent");
    }
    SessionStore local(middle, core::storage::Database::Access::ReadOnly);
    return local.sessions().front().uuid;
}

void measure(testing::PostgresServer& server, const fs::path& folder, const Shape& shape, double fraction, int index)
{
    const auto count = static_cast<long long>(static_cast<double>(shape.sessions) * fraction);
    const std::string big = "scale" + std::to_string(index), small = "base" + std::to_string(index);
    const std::string bigUuid = makeStore(server, folder, shape, big, count);
    const std::string smallUuid = makeStore(server, folder, shape, small, count / 100);
    CentralStore atScale(server.conninfo("quality", big)), baseline(server.conninfo("quality", small));
    PgConnection owner(server.conninfo(testing::PostgresServer::kOwner, big));
    const auto size = [&](const std::string& sql) { return owner.query(sql).text(0, 0); };
    std::cout << "\n### " << shape.name << ": " << count << " sessions, " << shape.stations << " stations\n\n"
              << "sessions table " << size("SELECT pg_size_pretty(pg_total_relation_size('sessions'))")
              << ", chunk rows " << size("SELECT count(*) FROM chunks") << ", database "
              << size("SELECT pg_size_pretty(pg_database_size(current_database()))") << "\n\n"
              << "| question | at scale (ms) | baseline, 1/100 (ms) | ratio | indexes read |\n"
              << "| --- | --- | --- | --- | --- |\n";
    const auto scaleQuestions = questions(shape, bigUuid), baseQuestions = questions(shape, smallUuid);
    for (std::size_t i = 0; i < scaleQuestions.size(); ++i) {
        const double scaled = medianMs([&] { scaleQuestions[i].ask(atScale); });
        const double base = medianMs([&] { baseQuestions[i].ask(baseline); });
        const std::string plan =
            scaleQuestions[i].listing ? planShape(atScale.listingPlan(*scaleQuestions[i].listing)) : "primary keys";
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %.1f | %.1f | %.2f | %s |\n", scaleQuestions[i].what.c_str(), scaled,
                      base, scaled / base, plan.c_str());
        std::cout << line << std::flush;
    }
}

}  // namespace

int main(int argc, char** argv)
{
    const double fraction = argc > 1 ? std::stod(argv[1]) : 1.0;
    const fs::path folder = fs::temp_directory_path() / ("tactiscope-scale-bench-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    auto server = std::make_unique<testing::PostgresServer>();
    {
        PgConnection owner(server->conninfo());
        core::storage::central::initCentralStore(owner);  // the roles
        owner.run("CREATE ROLE quality LOGIN IN ROLE tactiscope_reviewer");
    }
    std::cout << "Central store at scale (bench/CentralScaleBenchmark.cpp, fraction " << fraction
              << "): median of 5 warm runs as a reviewer, against a store of a hundredth of the size in the same "
                 "run\n";
    measure(*server, folder, kClinic, fraction, 1);
    measure(*server, folder, kPress, fraction, 2);
    server.reset();
    fs::remove_all(folder);
    return 0;
}
