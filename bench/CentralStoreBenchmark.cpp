// The central store against a station's SQLite store, in the same run, on
// a PostgreSQL server started here (unix socket, as the tests start it):
//  - listing 1 000 sessions with a filter (the browser's query), both
//    stores;
//  - the overview of a 1 h × 8 ch × 2 kHz session (every channel at 1 920
//    points, a review window's first paint), both stores;
//  - sending that hour (sync, one transaction) against reading and
//    checksumming its chunks from the station's store (the sync's local
//    half), in samples per second.
// Times are wall-clock (UseRealTime): the server's work is in another
// process, which CPU time would leave out. Run with
// --benchmark_repetitions=3; docs/performance.md quotes the fastest.
#include "Fastest.h"

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/CentralSync.h"
#include "support/PostgresServer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <unistd.h>

namespace {

using namespace tactiscope;
using core::storage::SessionStore;
using core::storage::central::CentralStore;
using core::storage::central::PgConnection;
namespace fs = std::filesystem;

constexpr int kSessions = 1000;
constexpr std::size_t kChannels = 8;
constexpr double kRate_hz = 2000.0;
constexpr std::uint64_t kHourSamples = 3600 * 2000;  // per channel
constexpr std::size_t kPoints = 1920;                // a full-HD screen's width

// 1 000 short sessions, and one hour of eight channels; both sent to the
// central store (as the owner, in one station's name).
struct Site {
    fs::path folder = fs::temp_directory_path() / ("tactiscope-central-bench-" + std::to_string(::getpid()));
    std::unique_ptr<testing::PostgresServer> server;
    std::string many, hour;
    std::int64_t localHour = 0, centralHour = 0;

    Site()
    {
        fs::create_directories(folder);
        server = std::make_unique<testing::PostgresServer>();
        PgConnection owner(server->conninfo());
        core::storage::central::initCentralStore(owner);
        many = (folder / "many.tactiscope").string();
        hour = (folder / "hour.tactiscope").string();
        writeMany();
        writeHour();
        CentralStore central(server->conninfo());
        core::storage::SessionStore local(many, core::storage::Database::Access::ReadOnly);
        core::storage::central::syncToCentral(local, central, "press-line");
        SessionStore hourStore(hour, core::storage::Database::Access::ReadOnly);
        localHour = hourStore.sessions().front().id;
        core::storage::central::syncToCentral(hourStore, central, "press-line");
        centralHour = *central.sessionWithUuid(hourStore.sessions().front().uuid);
    }
    ~Site()
    {
        server.reset();
        std::error_code ignored;
        fs::remove_all(folder, ignored);
    }

    void writeMany() const
    {
        SessionStore store(many);
        const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain},
                                                            {"b", "", core::ChannelKind::Strain}};
        for (int i = 0; i < kSessions; ++i) {
            core::storage::SessionMetadata m;
            m.mode = static_cast<core::Mode>(i % 3);
            m.subject = (i % 2 ? "door-" : "hood-") + std::to_string(i);
            m.operatorName = i % 3 ? "Ada" : "Grace";
            const auto id = store.beginSession(m, channels, 100.0);
            core::SampleBlock block(2, 100, 0.0, 0.01, 0);
            for (std::size_t s = 0; s < 100; ++s)
                block.channel(0)[s] = block.channel(1)[s] = std::sin(0.1 * static_cast<double>(s));
            store.appendBlocks(id, std::vector{block});
            store.endSession(id, core::SessionStatus::Complete);
        }
    }

    void writeHour() const
    {
        SessionStore store(hour);
        std::vector<core::ChannelDescriptor> channels;
        for (std::size_t c = 0; c < kChannels; ++c)
            channels.push_back({"ch" + std::to_string(c), "", core::ChannelKind::Strain});
        core::storage::SessionMetadata m;
        m.subject = "hour";
        const auto id = store.beginSession(m, channels, kRate_hz);
        constexpr std::size_t kBlock = 4096;
        for (std::uint64_t first = 0; first < kHourSamples; first += kBlock) {
            core::SampleBlock block(kChannels, kBlock, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
            for (std::size_t c = 0; c < kChannels; ++c)
                for (std::size_t s = 0; s < kBlock; ++s)
                    block.channel(c)[s] = std::sin(1e-3 * static_cast<double>(first + s) * static_cast<double>(c + 1));
            store.appendBlocks(id, std::vector{block});
        }
        store.endSession(id, core::SessionStatus::Complete);
    }
};

Site& site()
{
    static Site s;
    return s;
}

core::storage::SessionFilter filter()
{
    core::storage::SessionFilter f;
    f.startedFrom = "2000";  // all of them: the longest answer
    f.text = "o";            // every subject matches: a text search over all columns
    return f;
}

void listSessions(benchmark::State& state, core::storage::SessionSource& store)
{
    std::size_t listed = 0;
    for (auto _ : state) listed = store.sessions(filter()).size();
    state.counters["sessions"] = static_cast<double>(listed);
}

void BM_List_Sqlite(benchmark::State& state)
{
    SessionStore store(site().many, core::storage::Database::Access::ReadOnly);
    listSessions(state, store);
}

void BM_List_Central(benchmark::State& state)
{
    CentralStore store(site().server->conninfo());
    listSessions(state, store);
}

void overview(benchmark::State& state, core::storage::SessionSource& store, std::int64_t session)
{
    for (auto _ : state)
        for (std::size_t c = 0; c < kChannels; ++c)
            benchmark::DoNotOptimize(store.overview(session, c, 0, kHourSamples, kPoints));
}

// A connection per iteration, as a review window opens its own.
void BM_Overview_Sqlite(benchmark::State& state)
{
    SessionStore store(site().hour, core::storage::Database::Access::ReadOnly);
    overview(state, store, site().localHour);
}

void BM_Overview_Central(benchmark::State& state)
{
    CentralStore store(site().server->conninfo());
    overview(state, store, site().centralHour);
}

void countSamples(benchmark::State& state)
{
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kHourSamples * kChannels));
}

// The sync's local half: every chunk read and checksummed.
void BM_SyncLocalHalf_Hour(benchmark::State& state)
{
    SessionStore store(site().hour, core::storage::Database::Access::ReadOnly);
    for (auto _ : state) benchmark::DoNotOptimize(core::storage::central::sessionChecksum(store, site().localHour));
    countSamples(state);
}

void BM_Sync_Hour(benchmark::State& state)
{
    SessionStore local(site().hour, core::storage::Database::Access::ReadOnly);
    for (auto _ : state) {
        state.PauseTiming();
        {
            PgConnection owner(site().server->conninfo());
            owner.run("DELETE FROM sessions WHERE subject = 'hour'");
        }
        CentralStore central(site().server->conninfo());
        state.ResumeTiming();
        const auto outcome = core::storage::central::syncToCentral(local, central, "press-line");
        if (outcome.sent != 1) state.SkipWithError("the hour was not sent");
    }
    countSamples(state);
}

}  // namespace

BENCHMARK(BM_List_Sqlite)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_List_Central)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_Overview_Sqlite)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_Overview_Central)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_SyncLocalHalf_Hour)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_Sync_Hour)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->ComputeStatistics("min", tactiscope::bench::fastest);

BENCHMARK_MAIN();
