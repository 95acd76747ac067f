// The signal tools' cost (issue 57), each against a baseline of the same
// run (docs/performance.md, "Signal tools"):
//  - filtering 16 channels × 10 kHz, each through a 50 Hz mains notch (and
//    its harmonics) and a 4th-order 100 Hz low-pass, block by block as the
//    live path would, against the live buffer taking the same blocks (what
//    every sample costs already); its time per second of stream is the
//    fraction of a core the filters take;
//  - a live spectrum frame, 8 channels × 8,192 points (Hann density and
//    flat-top lines), against the display's own frame work on the same
//    points (min/max decimation to 1,600 columns);
//  - one channel's health over an hour at 1 kHz, against reading the same
//    samples' sum (a pass over them);
//  - a capacitive beam's creep over an hour at 10 Hz of load steps every
//    20 s, against the health of the same hour.
// Run: tactiscope_signal_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "EightChannelStream.h"
#include "core/LiveBuffer.h"
#include "core/SampleBlock.h"
#include "core/dsp/ChannelFilter.h"
#include "core/dsp/SignalHealth.h"
#include "core/dsp/StepCreep.h"
#include "core/dsp/WelchSpectrum.h"
#include "core/signal/MinMaxDecimation.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

namespace {

using namespace tactiscope;

constexpr std::size_t kWideChannels = 16;
constexpr double kWideRate_hz = 10000.0;
constexpr std::size_t kBlock = 50;  // 5 ms at 10 kHz, as the acquisition hands them on
constexpr std::size_t kBlocksPerSecond = 200;

std::vector<core::SampleBlock> secondOfBlocks()
{
    std::vector<core::SampleBlock> blocks;
    for (std::size_t b = 0; b < kBlocksPerSecond; ++b)
        blocks.push_back(bench::streamBlock(kWideChannels, kWideRate_hz, b * kBlock, kBlock));
    return blocks;
}

// Baseline: the live buffer taking a second of 16 × 10 kHz.
void BM_LiveBufferSecond(benchmark::State& state)
{
    const auto blocks = secondOfBlocks();
    core::LiveBuffer buffer(kWideChannels, static_cast<std::size_t>(kWideRate_hz) * 10);
    for (auto _ : state)
        for (const auto& block : blocks) buffer.consume(block);
    state.counters["core_fraction"] =
        benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_LiveBufferSecond)->Unit(benchmark::kMillisecond);

// A notch and a low-pass on every channel, a second of stream per iteration.
void BM_FilterSecond(benchmark::State& state)
{
    auto blocks = secondOfBlocks();
    core::dsp::FilterSettings settings;
    settings.notch_hz = 50.0;
    settings.lowpass_hz = 100.0;
    std::vector<core::dsp::ChannelFilter> filters;
    for (std::size_t c = 0; c < kWideChannels; ++c) filters.emplace_back(settings, kWideRate_hz);
    std::vector<double> values(kBlock);
    for (auto _ : state) {
        for (const auto& block : blocks) {
            for (std::size_t c = 0; c < kWideChannels; ++c) {
                const auto channel = block.channel(c);
                values.assign(channel.begin(), channel.end());
                filters[c].process(values);
                benchmark::DoNotOptimize(values.data());
            }
        }
    }
    state.counters["core_fraction"] =
        benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FilterSecond)->Unit(benchmark::kMillisecond);

constexpr std::size_t kSpectrumChannels = 8;
constexpr std::size_t kSpectrumPoints = 8192;
constexpr double kSpectrumRate_hz = 2000.0;

std::vector<std::vector<double>> spectrumWindow()
{
    const core::SampleBlock block = bench::streamBlock(kSpectrumChannels, kSpectrumRate_hz, 0, kSpectrumPoints);
    std::vector<std::vector<double>> channels;
    for (std::size_t c = 0; c < kSpectrumChannels; ++c)
        channels.emplace_back(block.channel(c).begin(), block.channel(c).end());
    return channels;
}

// Baseline: the display's frame on the same points (min/max to 1,600 columns).
void BM_DisplayFrameOfSpectrumWindow(benchmark::State& state)
{
    const auto channels = spectrumWindow();
    std::vector<double> t(kSpectrumPoints);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<double>(i) / kSpectrumRate_hz;
    std::vector<double> tOut, yOut;
    const double column_s = static_cast<double>(kSpectrumPoints) / kSpectrumRate_hz / 1600.0;
    for (auto _ : state)
        for (const auto& channel : channels) {
            core::signal::decimateMinMax(t, channel, column_s, tOut, yOut);
            benchmark::DoNotOptimize(yOut.data());
        }
}
BENCHMARK(BM_DisplayFrameOfSpectrumWindow)->Unit(benchmark::kMillisecond);

// A live spectrum frame: each channel's last 8,192 points as 7 half-
// overlapping segments of 2,048 (4 averages at least), through accumulators
// kept from frame to frame (their FFT plans and windows made once), as the
// spectrum view keeps its own (welchSpectrum with a kept accumulator).
void BM_SpectrumFrame(benchmark::State& state)
{
    const auto channels = spectrumWindow();
    const core::dsp::SpectrumSettings settings{core::dsp::SpectralWindow::Hann, 4};
    std::vector<std::unique_ptr<core::dsp::WelchAccumulator>> kept(kSpectrumChannels);
    for (auto _ : state)
        for (std::size_t c = 0; c < kSpectrumChannels; ++c) {
            const auto spectrum = core::dsp::welchSpectrum(channels[c], kSpectrumRate_hz, settings, kept[c]);
            benchmark::DoNotOptimize(spectrum.psd.data());
        }
}
BENCHMARK(BM_SpectrumFrame)->Unit(benchmark::kMillisecond);

constexpr std::size_t kHourAt1kHz = 3600 * 1000;

std::vector<double> hourOfSamples()
{
    const core::SampleBlock block = bench::streamBlock(1, 1000.0, 0, kHourAt1kHz);
    return {block.channel(0).begin(), block.channel(0).end()};
}

// Baseline: one pass summing the hour.
void BM_PassOverAnHour(benchmark::State& state)
{
    const auto hour = hourOfSamples();
    for (auto _ : state) benchmark::DoNotOptimize(std::accumulate(hour.begin(), hour.end(), 0.0));
}
BENCHMARK(BM_PassOverAnHour)->Unit(benchmark::kMillisecond);

void BM_HealthOfAnHour(benchmark::State& state)
{
    const auto hour = hourOfSamples();
    for (auto _ : state) {
        core::dsp::HealthAccumulator health(1000.0, hour.size());
        for (std::size_t at = 0; at < hour.size(); at += 65536)
            health.push(std::span(hour).subspan(at, std::min<std::size_t>(65536, hour.size() - at)));
        benchmark::DoNotOptimize(health.result().noiseFloor_per_sqrt_hz);
    }
}
BENCHMARK(BM_HealthOfAnHour)->Unit(benchmark::kMillisecond);

// An hour of a beam at 10 Hz: a weight on or off every 20 s, settling with
// 0.4 s and creeping 5 % further with 4 s, under white noise of 1 % of a step.
std::vector<double> hourOfSteps()
{
    constexpr double rate = 10.0, dt = 1.0 / rate;
    const double settle = 1.0 - std::exp(-dt / 0.4), creep = 1.0 - std::exp(-dt / 4.0);
    std::mt19937_64 random(1);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::vector<double> y(3600 * 10);
    double settled = 0.0, crept = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        const auto step = static_cast<int>(static_cast<double>(i) * dt / 20.0);
        const double load = step % 2 ? 100.0 * (step % 7 + 1) : 0.0;
        settled += (load - settled) * settle;
        crept += (0.05 * settled - crept) * creep;
        y[i] = settled + crept + noise(random);
    }
    return y;
}

// Baseline: the same hour's health.
void BM_HealthOfAnHourOfSteps(benchmark::State& state)
{
    const auto hour = hourOfSteps();
    for (auto _ : state) {
        core::dsp::HealthAccumulator health(10.0, hour.size());
        health.push(hour);
        benchmark::DoNotOptimize(health.result().noiseFloor_per_sqrt_hz);
    }
}
BENCHMARK(BM_HealthOfAnHourOfSteps)->Unit(benchmark::kMillisecond);

void BM_CreepOfAnHourOfSteps(benchmark::State& state)
{
    const auto hour = hourOfSteps();
    for (auto _ : state) benchmark::DoNotOptimize(core::dsp::findStepCreep(hour, 10.0));
}
BENCHMARK(BM_CreepOfAnHourOfSteps)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
