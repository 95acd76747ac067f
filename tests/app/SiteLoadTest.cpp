// A site at full load (issue 36, item 11): a hundred stations, each its own
// store and station login holding a shift's sessions, run `tactiscope-cli
// sync` at once against one PostgreSQL server on this machine; once a third
// of the sessions have arrived the server is killed (SIGKILL, every
// process) and started again two seconds later. Each station retries as
// its scheduler would (a failed sync again after a second) until its sync
// succeeds. Then the server holds exactly the stations' sessions: every
// uuid once, nothing unfinished, every station's sample bytes to the byte.
// The same shift synced by one station alone, and by the hundred without a
// crash, are the baselines; the runs' time, throughput and server CPU are
// printed for docs/fleet.md (never asserted: wall time is the machine's,
// not the product's). TACTISCOPE_SITE_SHIFT_ROUNDS sets the shift's length
// (rounds of three sessions; 10 by default) for longer measurements.
#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/PgConnection.h"
#include "support/PostgresServer.h"
#include "support/StationStore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

using namespace tactiscope;
using core::storage::SessionStore;
using core::storage::central::PgConnection;
using tactiscope::testing::PostgresServer;

namespace {

constexpr int kStations = 100;

// A shift: rounds of a station's three kinds of session (a panel scan with
// a gap, a palpation with readings and a calibration, an interrupted
// capacitive recording).
int shiftRounds()
{
    const char* rounds = std::getenv("TACTISCOPE_SITE_SHIFT_ROUNDS");
    return rounds ? std::max(1, std::atoi(rounds)) : 10;
}

using Clock = std::chrono::steady_clock;

std::string stationName(int station)
{
    char name[32];
    std::snprintf(name, sizeof name, "station_%03d", station);
    return name;
}

// What a store holds, as the sync must copy it: its sessions' uuids and
// their sample bytes.
struct Holdings {
    std::set<std::string> uuids;
    std::uint64_t sampleBytes = 0;
    bool operator==(const Holdings&) const = default;
};

Holdings localHoldings(const std::string& path)
{
    SessionStore store(path);
    Holdings h;
    for (const auto& s : store.sessions()) {
        h.uuids.insert(s.uuid);
        store.forEachChunk(s.id, [&](const SessionStore::RawChunk& c) { h.sampleBytes += c.samples.size(); });
    }
    return h;
}

std::map<std::string, Holdings> serverHoldings(PgConnection& owner)
{
    std::map<std::string, Holdings> result;
    const auto sessions = owner.query("SELECT station, uuid FROM sessions WHERE complete");
    for (int i = 0; i < sessions.rows(); ++i) result[sessions.text(i, 0)].uuids.insert(sessions.text(i, 1));
    const auto bytes = owner.query("SELECT s.station, sum(octet_length(c.samples)) FROM chunks c "
                                   "JOIN sessions s ON s.id = c.session_id GROUP BY s.station");
    for (int i = 0; i < bytes.rows(); ++i) result[bytes.text(i, 0)].sampleBytes = std::stoull(bytes.text(i, 1));
    return result;
}

// One station's sync as a process of its own, its output in a file.
pid_t startSync(const std::string& store, const std::string& server, const std::string& log)
{
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    std::vector<std::string> args{TACTISCOPE_CLI, "sync", "--db", store, "--server", server};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    return failed == 0 ? pid : -1;
}

struct RunFigures {
    double seconds = 0.0;
    double serverCpu_s = 0.0;
    int attempts = 0;  // syncs started, the retries included
    int failedAttempts = 0;
};

class SiteLoad : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir = std::filesystem::temp_directory_path() / ("tactiscope-site-" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_dir);
        PgConnection owner(m_server.conninfo());
        for (const char* database : {"alone", "calm", "site"}) {
            owner.run(std::string("CREATE DATABASE ") + database);
            PgConnection store(m_server.conninfo(PostgresServer::kOwner, database));
            core::storage::central::initCentralStore(store);
        }
        std::string roles;  // (a cluster's roles serve all its databases)
        for (int s = 0; s < kStations; ++s)
            roles += "CREATE ROLE " + stationName(s) + " LOGIN IN ROLE tactiscope_station;\n";
        owner.run(roles);
        // The shifts, written on both cores.
        const auto write = [this](int from) {
            for (int s = from; s < kStations; s += 2)
                for (int round = 0; round < m_rounds; ++round) {
                    tactiscope::testing::StationStoreOptions o;
                    o.subjectPrefix = "door-" + std::to_string(s);
                    o.seed = s * m_rounds + round;
                    tactiscope::testing::writeStationStore(store(s), o);
                }
        };
        std::thread other(write, 1);
        write(0);
        other.join();
    }
    void TearDown() override
    {
        std::error_code ignored;
        std::filesystem::remove_all(m_dir, ignored);
    }

    std::string store(int station) const { return (m_dir / (stationName(station) + ".tactiscope")).string(); }
    std::string log(int station) const { return (m_dir / (stationName(station) + ".log")).string(); }

    // Syncs `stations` at once into `database`, each again a second after
    // a failure, until all have succeeded; `during` is called every 50 ms
    // with the sessions the server holds complete.
    RunFigures syncAll(const std::vector<int>& stations, const std::string& database,
                       const std::function<void(std::int64_t arrived)>& during = {})
    {
        RunFigures figures;
        const double cpuBefore = m_server.cpuSeconds();
        const auto started = Clock::now();
        std::map<pid_t, int> running;
        std::map<int, Clock::time_point> retryAt;
        const auto launch = [&](int s) {
            const pid_t pid = startSync(store(s), m_server.conninfo(stationName(s), database), log(s));
            ASSERT_GT(pid, 0) << "cannot start " << TACTISCOPE_CLI;
            running[pid] = s;
            ++figures.attempts;
        };
        for (const int s : stations) launch(s);
        std::unique_ptr<PgConnection> watcher;
        while (!running.empty() || !retryAt.empty()) {
            if (Clock::now() - started > std::chrono::minutes(10)) {
                ADD_FAILURE() << running.size() + retryAt.size() << " stations still not synced after 10 min";
                for (const auto& [pid, station] : running) ::kill(pid, SIGKILL);
                break;
            }
            int status = 0;
            for (pid_t pid; (pid = ::waitpid(-1, &status, WNOHANG)) > 0;) {
                const auto found = running.find(pid);
                if (found == running.end()) continue;
                if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
                    ++figures.failedAttempts;
                    retryAt[found->second] = Clock::now() + std::chrono::seconds(1);
                }
                running.erase(found);
            }
            for (auto it = retryAt.begin(); it != retryAt.end();) {
                if (Clock::now() < it->second) {
                    ++it;
                    continue;
                }
                launch(it->first);
                it = retryAt.erase(it);
            }
            if (during) {
                try {
                    if (!watcher)
                        watcher = std::make_unique<PgConnection>(m_server.conninfo(PostgresServer::kOwner, database));
                    during(watcher->query("SELECT count(*) FROM sessions WHERE complete").int64(0, 0));
                } catch (const core::storage::StorageError&) {
                    watcher.reset();  // the server is down: ask again once it is back
                }
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        figures.seconds = std::chrono::duration<double>(Clock::now() - started).count();
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the backends reaped
        figures.serverCpu_s = m_server.cpuSeconds() - cpuBefore + m_cpuBeforeCrash;
        return figures;
    }

    const int m_rounds = shiftRounds();
    PostgresServer m_server;
    std::filesystem::path m_dir;
    double m_cpuBeforeCrash = 0.0;  // what the killed server had used
};

}  // namespace

TEST_F(SiteLoad, AHundredStationsSyncAShiftAtOnceThroughAServerCrash)
{
    std::vector<int> everyone;
    std::map<std::string, Holdings> expected;
    for (int s = 0; s < kStations; ++s) {
        everyone.push_back(s);
        expected[stationName(s)] = localHoldings(store(s));
    }
    const std::uint64_t shiftBytes = expected[stationName(0)].sampleBytes;
    const std::int64_t total = static_cast<std::int64_t>(kStations) * m_rounds * 3;
    ASSERT_EQ(expected[stationName(0)].uuids.size(), static_cast<std::size_t>(m_rounds * 3));

    const RunFigures alone = syncAll({0}, "alone");
    EXPECT_EQ(alone.failedAttempts, 0);
    const RunFigures calm = syncAll(everyone, "calm");
    EXPECT_EQ(calm.failedAttempts, 0);

    bool crashed = false;
    double crashedAt_s = 0.0;
    const auto started = Clock::now();
    const RunFigures site = syncAll(everyone, "site", [&](std::int64_t arrived) {
        if (crashed || arrived < total / 3) return;
        crashed = true;
        crashedAt_s = std::chrono::duration<double>(Clock::now() - started).count();
        m_cpuBeforeCrash = m_server.cpuSeconds();
        m_server.crash();
        std::this_thread::sleep_for(std::chrono::seconds(2));
        m_server.start();
    });
    ASSERT_TRUE(crashed) << "the run ended before a third of the sessions had arrived";
    EXPECT_GT(site.failedAttempts, 0) << "the crash interrupted no sync";

    // Nothing lost, nothing twice, nothing half-sent, in both runs.
    for (const char* database : {"calm", "site"}) {
        PgConnection owner(m_server.conninfo(PostgresServer::kOwner, database));
        const auto counts = owner.query("SELECT count(*), count(DISTINCT uuid) FROM sessions");
        EXPECT_EQ(counts.text(0, 0), std::to_string(total)) << database;
        EXPECT_EQ(counts.text(0, 1), std::to_string(total)) << database;
        EXPECT_EQ(owner.query("SELECT count(*) FROM sessions WHERE NOT complete").text(0, 0), "0") << database;
        const auto held = serverHoldings(owner);
        for (const auto& [station, holdings] : expected) {
            const auto found = held.find(station);
            ASSERT_NE(found, held.end()) << station << " has nothing on the server";
            EXPECT_TRUE(found->second == holdings)
                << database << ", " << station << ": " << found->second.uuids.size() << " sessions, "
                << found->second.sampleBytes << " bytes on the server; " << holdings.uuids.size() << ", "
                << holdings.sampleBytes << " at the station";
        }
    }

    const double shiftMB = static_cast<double>(shiftBytes) / 1e6;
    const auto report = [&](const char* what, int stations, const RunFigures& run) {
        std::printf("%s: %d × %d sessions, %.1f MB of samples in %.2f s: %.2f MB/s, %.0f sessions/s; server CPU "
                    "%.2f s (%.3f s a station, %.0f %% of one core); %d syncs started, %d failed and retried\n",
                    what, stations, m_rounds * 3, shiftMB * stations, run.seconds, shiftMB * stations / run.seconds,
                    stations * m_rounds * 3 / run.seconds, run.serverCpu_s, run.serverCpu_s / stations,
                    100.0 * run.serverCpu_s / run.seconds, run.attempts, run.failedAttempts);
    };
    report("one station alone", 1, alone);
    report("100 stations at once", kStations, calm);
    report("100 stations, server killed", kStations, site);
    std::printf("(killed at %.1f s, started again 2 s later)\n", crashedAt_s);
}
