// What a user runs against what the kernel costs: one hour of the simulated
// panel scan (2 cantilevers, 500 Hz, the paper's 75 lags), re-analysed end
// to end — from the session store to events (`analyze`, the review), from a
// CSV file to events (`detect`), from a CSV file to per-sample rows
// (`detect --output`) — beside the kernel alone on the same samples held in
// memory, and the direct implementation, all in one run so the ratios hold
// on a shared machine. Run with
//   tactiscope_end_to_end_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "DirectDetector.h"
#include "core/SampleBlock.h"
#include "core/derived/StoredDetection.h"
#include "core/detector/CsvDetection.h"
#include "core/detector/PairDetector.h"
#include "core/storage/CsvImport.h"
#include "core/text/NumberFormat.h"
#include "devices/simulator/PanelScanScenario.h"

#include "Fastest.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <vector>

namespace {

using namespace tactiscope;
namespace fs = std::filesystem;

constexpr std::size_t kHour = 3600 * 500;

// The hour, written once as a CSV file and imported into a store, in a
// folder removed at exit.
struct Hour {
    std::vector<double> a, b;
    fs::path folder;
    std::string csv, store;
    std::int64_t session = 0;

    Hour()
    {
        devices::simulator::PanelScanScenario scenario;
        core::SampleBlock block(2, kHour, 0.0, 0.002);
        scenario.generate(block);
        a.assign(block.channel(0).begin(), block.channel(0).end());
        b.assign(block.channel(1).begin(), block.channel(1).end());
        folder = fs::temp_directory_path() / ("tactiscope-e2e-" + std::to_string(::getpid()));
        fs::create_directories(folder);
        csv = (folder / "hour.csv").string();
        store = (folder / "hour.tactiscope").string();
        std::ofstream out(csv, std::ios::binary);
        std::string row = "t [s],a [strain],b [strain]\n";
        for (std::size_t i = 0; i < kHour; ++i) {
            core::text::appendShortest(row, block.timeAt_s(i));
            row += ',';
            core::text::appendShortest(row, a[i]);
            row += ',';
            core::text::appendShortest(row, b[i]);
            row += '\n';
            if (row.size() > (1u << 20)) {
                out << row;
                row.clear();
            }
        }
        out << row;
        out.close();
        core::storage::SessionStore sessions(store);
        session = core::storage::importCsv(sessions, csv, {}).session;
    }
    ~Hour()
    {
        std::error_code ignored;
        fs::remove_all(folder, ignored);
    }
};

const Hour& hour()
{
    static const Hour data;
    return data;
}

core::detector::StretchSettings settings(unsigned threads)
{
    core::detector::StretchSettings s;
    s.parameters.sampleInterval_s = 0.002;
    s.spacing_m = core::detector::kPrototypeSpacing_m;
    s.threads = threads;
    return s;
}

void countSamples(benchmark::State& state)
{
    state.counters["samples_per_s"] =
        benchmark::Counter(static_cast<double>(kHour), benchmark::Counter::kIsIterationInvariantRate);
}

// The baseline: the vectorised kernel over samples already in memory.
void BM_Kernel_1h(benchmark::State& state)
{
    const Hour& data = hour();
    std::vector<core::detector::DetectorOutput> out(kHour);
    for (auto _ : state) {
        core::detector::PairDetector detector(settings(1).parameters);
        detector.process(data.a, data.b, out);
        benchmark::DoNotOptimize(out.data());
    }
    countSamples(state);
}

// The direct Eigen implementation, for the ratio the issue asks (≥ 8×).
void BM_Direct_1h(benchmark::State& state)
{
    const Hour& data = hour();
    std::vector<core::detector::DetectorOutput> out(kHour);
    for (auto _ : state) {
        reference::DirectDetector detector(settings(1).parameters);
        detector.process(data.a, data.b, out);
        benchmark::DoNotOptimize(out.data());
    }
    countSamples(state);
}

// `analyze`: the store, a window at a time, to events. Argument: threads.
void BM_StoreToEvents_1h(benchmark::State& state)
{
    const Hour& data = hour();
    core::storage::SessionStore store(data.store, core::storage::Database::Access::ReadOnly);
    const std::vector<std::size_t> cantilevers{0, 1};
    for (auto _ : state) {
        const auto found = core::derived::detectStoredSession(store, data.session, cantilevers,
                                                              settings(static_cast<unsigned>(state.range(0))));
        benchmark::DoNotOptimize(found->events.data());
    }
    countSamples(state);
}

// `detect`: the CSV file to events. Argument: threads.
void BM_CsvToEvents_1h(benchmark::State& state)
{
    const Hour& data = hour();
    for (auto _ : state) {
        const auto found =
            core::detector::detectCsv(data.csv, {"t", "a", "b"}, settings(static_cast<unsigned>(state.range(0))));
        benchmark::DoNotOptimize(found.events.data());
    }
    countSamples(state);
}

// `detect --output`: the CSV file to a per-sample CSV file.
void BM_CsvToSampleCsv_1h(benchmark::State& state)
{
    const Hour& data = hour();
    const std::string output = (data.folder / "out.csv").string();
    for (auto _ : state) {
        std::ofstream out(output, std::ios::binary | std::ios::trunc);
        out << core::detector::kSampleRowsHeader;
        std::string rows;
        core::detector::detectCsv(data.csv, {"t", "a", "b"}, settings(1),
                                  [&](std::span<const core::detector::ProbeOutput> outputs, double interval_s) {
                                      core::detector::appendSampleRows(rows, outputs, interval_s);
                                      out << rows;
                                  });
    }
    countSamples(state);
}

}  // namespace

BENCHMARK(BM_Kernel_1h)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_StoreToEvents_1h)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Arg(1)
    ->Arg(2)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_CsvToEvents_1h)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Arg(1)
    ->Arg(2)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_CsvToSampleCsv_1h)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_Direct_1h)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
