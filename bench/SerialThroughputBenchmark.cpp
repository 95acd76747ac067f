// Serial throughput: 8 channels at 2 kHz in TSP/1 frames over a pseudo-
// terminal at 921600 baud for 60 s, from the emulator (its own thread) to the
// reader (this thread, doing exactly what the acquisition thread does).
// Reported: samples lost, and the reading thread's CPU time as a fraction of
// one core, for the full decode path and, as the baseline, for reading the
// raw bytes only.
#include "core/SampleBlock.h"
#include "devices/PortSource.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/transport/SerialPorts.h"

#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace tactiscope::devices;
constexpr double kSeconds = 60.0;

double threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

emulator::EmulatorOptions eightChannels(const std::string& link)
{
    emulator::EmulatorOptions options;
    options.linkPath = link;
    options.scenario = simulator::kPanelScanScenario;
    options.rate_hz = 2000.0;
    options.channels = 8u;
    options.seconds = kSeconds;
    return options;
}

std::string linkPath()
{
    return (std::filesystem::temp_directory_path() / ("tactiscope-bench-" + std::to_string(::getpid()))).string();
}

void BM_SerialDecode8x2kHz(benchmark::State& state)
{
    for (auto _ : state) {
        emulator::ProbeEmulator probe(eightChannels(linkPath()));
        probe.start();
        PortSource source(transport::openSerialTransport(linkPath(), 921600), {});
        const double cpu0 = threadCpuSeconds();
        const auto wall0 = std::chrono::steady_clock::now();
        std::uint64_t samples = 0;
        tactiscope::core::SampleBlock block;
        for (;;) {
            const auto status = source.readBlock(block, std::chrono::milliseconds(100));
            if (status == ReadStatus::Failed) break;  // the emulator hung up after 60 s
            if (status == ReadStatus::Block) samples += block.sampleCount();
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        state.counters["cpu_fraction"] = (threadCpuSeconds() - cpu0) / wall;
        state.counters["samples"] = static_cast<double>(samples);
        state.counters["samples_sent"] = static_cast<double>(probe.stats().samplesSent);
        state.counters["samples_lost"] = static_cast<double>(source.decoderCounters().samplesLost);
        state.counters["dropped_by_emulator"] = static_cast<double>(probe.stats().droppedFrames);
    }
}

void BM_SerialRawBytes8x2kHz(benchmark::State& state)
{
    for (auto _ : state) {
        emulator::ProbeEmulator probe(eightChannels(linkPath()));
        probe.start();
        auto port = transport::openSerialTransport(linkPath(), 921600);
        // The emulator streams only after start: send it by hand.
        const std::vector<std::uint8_t> start{0xA5, 0x5A, 0x01, 0x10, 0x01, 0x00, 0x00, 0x00, 0x01, 0x5B, 0xE9};
        port->write(start);
        const double cpu0 = threadCpuSeconds();
        const auto wall0 = std::chrono::steady_clock::now();
        std::vector<std::uint8_t> buffer(4096);
        std::uint64_t bytes = 0;
        try {
            for (;;) bytes += port->read(buffer, std::chrono::milliseconds(100));
        } catch (const transport::TransportError&) {
            // hung up after 60 s
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        state.counters["cpu_fraction"] = (threadCpuSeconds() - cpu0) / wall;
        state.counters["bytes"] = static_cast<double>(bytes);
    }
}

}  // namespace

BENCHMARK(BM_SerialRawBytes8x2kHz)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_SerialDecode8x2kHz)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
