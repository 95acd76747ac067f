// Detector speed: the vectorised PairDetector against the direct Eigen
// implementation and the probe's own single-precision kernel
// (FirmwarePairDetector, firmware/probe-detector, scalar C as a probe runs
// it), all single-threaded on the same simulated panel scan with the
// paper's settings (75 lags, 500 Hz). Reported per sample·lag so the two
// compare directly; the fast one also over a whole hour, the target.
// Run with repetitions for the min/median statistics, e.g.
//   tactiscope_detector_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include "DirectDetector.h"
#include "core/SampleBlock.h"
#include "core/detector/FirmwarePairDetector.h"
#include "core/detector/PairDetector.h"
#include "devices/simulator/PanelScanScenario.h"

#include "Fastest.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace {

using namespace tactiscope;

struct Scan {
    std::vector<double> a, b;
};

// `seconds` of the simulated hand scan over a dented panel at 500 Hz.
const Scan& scan(double seconds)
{
    static std::vector<std::pair<double, Scan>> cache;
    for (const auto& [s, data] : cache) {
        if (s == seconds) return data;
    }
    devices::simulator::PanelScanScenario scenario;
    const auto n = static_cast<std::size_t>(seconds * 500.0);
    core::SampleBlock block(2, n, 0.0, 0.002);
    scenario.generate(block);
    Scan data{{block.channel(0).begin(), block.channel(0).end()}, {block.channel(1).begin(), block.channel(1).end()}};
    cache.emplace_back(seconds, std::move(data));
    return cache.back().second;
}

template <typename Detector, typename... Options>
void run(benchmark::State& state, double seconds, Options... options)
{
    const Scan& data = scan(seconds);
    const core::detector::DetectorParameters parameters;
    std::vector<core::detector::DetectorOutput> out(data.a.size());
    for (auto _ : state) {
        Detector detector(parameters, options...);
        detector.process(data.a, data.b, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    const auto sampleLags = static_cast<double>(data.a.size() * parameters.lags_s.size());
    state.counters["ns_per_sample_lag"] = benchmark::Counter(
        sampleLags * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["samples_per_s"] =
        benchmark::Counter(static_cast<double>(data.a.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_DirectEigenInverse_60s(benchmark::State& state)
{
    run<reference::DirectDetector>(state, 60.0);
}

// Argument: the kernel variant (0 baseline, 1 AVX2, 2 AVX-512).
void BM_PairDetector_60s(benchmark::State& state)
{
    const auto variant = static_cast<core::detector::KernelVariant>(state.range(0));
    if (!core::detector::kernelVariantSupported(variant)) {
        state.SkipWithError("CPU lacks this instruction set");
        return;
    }
    state.SetLabel(core::detector::toString(variant));
    run<core::detector::PairDetector>(state, 60.0, variant);
}

// The target: one hour of 500 Hz data, the best variant, one core.
void BM_PairDetector_1h(benchmark::State& state)
{
    state.SetLabel(core::detector::toString(core::detector::bestKernelVariant()));
    run<core::detector::PairDetector>(state, 3600.0);
}

// The probe's kernel compiled for the workstation: what `detect --engine
// probe` runs, and a scalar single-precision loop like the probe's own.
void BM_FirmwarePairDetector_60s(benchmark::State& state)
{
    run<core::detector::FirmwarePairDetector>(state, 60.0);
}

}  // namespace

BENCHMARK(BM_DirectEigenInverse_60s)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_PairDetector_60s)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->DenseRange(0, 2)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_FirmwarePairDetector_60s)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->ComputeStatistics("min", tactiscope::bench::fastest);
BENCHMARK(BM_PairDetector_1h)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->ComputeStatistics("min", tactiscope::bench::fastest);

BENCHMARK_MAIN();
