// Session store speed, each against a baseline in the same run:
//  - recording 8 channels at 2 kHz through the Recorder (queue, writer
//    thread, SQLite, pyramid) against writing the same binary32 bytes to a
//    plain file: the cost of a crash-safe, indexed store over raw bytes;
//  - an overview of a one-hour, 8-channel, 2 kHz session (57.6 M samples)
//    at 2000 points per channel from the pyramid, against the direct min/max
//    over every sample;
//  - opening a store of 1000 sessions (one of them that hour) and listing
//    them, against opening the bare SQLite file.
// The store is built once in the temporary folder (about 250 MB, 20–40 s).
// Run: tactiscope_storage_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "EightChannelStream.h"
#include "core/SampleBlock.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/Recorder.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace tactiscope;
using bench::eightChannelBlock;
using bench::eightChannels;
using bench::kChannels;
using bench::kRate_hz;
using namespace tactiscope::core::storage;

constexpr std::size_t kFrame = 20;  // samples per channel in one device frame (10 ms)

std::string tempPath(const std::string& name)
{
    return (std::filesystem::temp_directory_path() / ("tactiscope-bench-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

void removeStore(const std::string& path)
{
    for (const char* suffix : {"", "-wal", "-shm", "-recorder.lock"}) std::filesystem::remove(path + suffix);
}

SessionMetadata panelScan()
{
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::PanelScan;
    return metadata;
}

// One minute of frames, made once and replayed.
const std::vector<core::SampleBlock>& minuteOfFrames()
{
    static const auto frames = [] {
        std::vector<core::SampleBlock> result;
        for (std::uint64_t first = 0; first < 60 * 2000; first += kFrame)
            result.push_back(eightChannelBlock(first, kFrame));
        return result;
    }();
    return frames;
}

void BM_RecordBaselineRawFile(benchmark::State& state)
{
    const auto& frames = minuteOfFrames();
    const std::string path = tempPath("raw.bin");
    for (auto _ : state) {
        std::FILE* file = std::fopen(path.c_str(), "wb");
        for (const auto& f : frames) {
            const auto bytes = encodeChunk(f);
            std::fwrite(bytes.data(), 1, bytes.size(), file);
        }
        std::fflush(file);
        ::fsync(fileno(file));
        std::fclose(file);
    }
    std::filesystem::remove(path);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(frames.size() * kFrame * kChannels));
}

void BM_RecordEightChannels2kHz(benchmark::State& state)
{
    const auto& frames = minuteOfFrames();
    const std::string path = tempPath("record.tactiscope");
    for (auto _ : state) {
        removeStore(path);
        Recorder recorder(path, panelScan(), eightChannels(), kRate_hz, 1'000'000);
        for (const auto& f : frames) recorder.consume(f);
        const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
        if (stats.samplesDropped > 0 || !stats.error.empty()) state.SkipWithError("samples were dropped");
    }
    removeStore(path);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(frames.size() * kFrame * kChannels));
    state.counters["x_real_time"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * 60.0, benchmark::Counter::kIsRate);
}

// The review fixture: 999 one-second sessions and one hour.
struct ReviewStore {
    std::string path = tempPath("review.tactiscope");
    std::int64_t hour = 0;
    std::uint64_t samples = 0;

    ReviewStore()
    {
        removeStore(path);
        SessionStore store(path);
        for (int s = 0; s < 999; ++s) {
            const auto id = store.beginSession(panelScan(), eightChannels(), kRate_hz);
            store.appendBlocks(id, std::vector{eightChannelBlock(0, 2000)});
            store.endSession(id, tactiscope::core::SessionStatus::Complete);
        }
        hour = store.beginSession(panelScan(), eightChannels(), kRate_hz);
        std::vector<core::SampleBlock> batch;
        for (std::uint64_t first = 0; first < 3600 * 2000; first += 4000) {
            batch.push_back(eightChannelBlock(first, 4000));
            if (batch.size() == 30) {
                store.appendBlocks(hour, batch);
                batch.clear();
            }
        }
        store.appendBlocks(hour, batch);
        store.endSession(hour, tactiscope::core::SessionStatus::Complete);
        samples = store.sampleCount(hour);
    }
    ~ReviewStore() { removeStore(path); }
};

ReviewStore& reviewStore()
{
    static ReviewStore store;
    return store;
}

void BM_OverviewBaselineEverySample(benchmark::State& state)
{
    auto& fixture = reviewStore();
    SessionStore store(fixture.path, Database::Access::ReadOnly);
    for (auto _ : state) {
        for (std::size_t c = 0; c < kChannels; ++c) {
            // Direct: every sample, in windows, min/max per point.
            double lo = INFINITY, hi = -INFINITY;
            for (std::uint64_t first = 0; first < fixture.samples; first += 1 << 20) {
                for (const double v : store.readChannel(fixture.hour, c, first, 1 << 20)) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
            }
            benchmark::DoNotOptimize(lo + hi);
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(fixture.samples * kChannels));
}

void BM_OverviewOneHourEightChannels(benchmark::State& state)
{
    auto& fixture = reviewStore();
    SessionStore store(fixture.path, Database::Access::ReadOnly);
    for (auto _ : state) {
        for (std::size_t c = 0; c < kChannels; ++c) {
            const auto points = store.overview(fixture.hour, c, 0, fixture.samples, 2000);
            benchmark::DoNotOptimize(points.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(fixture.samples * kChannels));
}

void BM_OpenBaselineBareSqlite(benchmark::State& state)
{
    auto& fixture = reviewStore();
    for (auto _ : state) {
        Database db(fixture.path, Database::Access::ReadOnly);
        auto count = db.prepare("SELECT count(*) FROM sqlite_schema");
        count.step();
        benchmark::DoNotOptimize(count.int64(0));
    }
}

void BM_OpenAndListThousandSessions(benchmark::State& state)
{
    auto& fixture = reviewStore();
    for (auto _ : state) {
        SessionStore store(fixture.path, Database::Access::ReadOnly);
        const auto sessions = store.sessions();
        if (sessions.size() != 1000) state.SkipWithError("expected 1000 sessions");
        benchmark::DoNotOptimize(sessions.data());
    }
}

}  // namespace

BENCHMARK(BM_RecordBaselineRawFile)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RecordEightChannels2kHz)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OverviewBaselineEverySample)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_OverviewOneHourEightChannels)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenBaselineBareSqlite)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenAndListThousandSessions)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
