// The built-in simulator as a device: turns a SimulatedScenario into a
// stream of SampleBlocks, either paced like a real probe (a block becomes
// available only when its last sample would have been measured) or as fast
// as the consumer takes them (tests, offline generation).
#pragma once

#include "devices/BlockSource.h"
#include "devices/simulator/ShuntedBridges.h"
#include "devices/simulator/SimulatedScenario.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

namespace tactiscope::devices::simulator {

enum class Pacing { RealTime, AsFastAsPossible };

struct SimulatorOptions {
    Pacing pacing = Pacing::RealTime;
    // At most this many samples a block (20 ms at 500 Hz: smooth, cheap to
    // pass around), and at most 20 ms of them: a 10 Hz beam sends each
    // sample as it comes, as a real one does, not a second's worth at once
    // (its readouts then lagged its traces by a block).
    std::size_t samplesPerBlock = 10;
    std::optional<double> duration_s;  // unlimited when empty
    // Real-time pacing only: simulated seconds per wall-clock second, so a
    // test can walk through a minute-long calibration in seconds.
    double speed = 1.0;
    // Real-time pacing only: a mark at this instant of the host's steady
    // clock (seconds; ClockMark.h), by the instants hostClock() states.
    std::optional<double> markAt_s = std::nullopt;
};

class SimulatorSource final : public BlockSource {
public:
    // Throws std::invalid_argument for a null scenario, zero samples per block,
    // a negative duration, a non-positive speed or a mark without pacing.
    SimulatorSource(std::unique_ptr<SimulatedScenario> scenario, const SimulatorOptions& options = {});

    std::string name() const override;
    // Model "Tactiscope simulator", the scenario as serial, the program's
    // version as firmware.
    DeviceIdentity identity() const override;
    std::optional<core::Mode> declaredMode() const override { return m_scenario->mode(); }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_scenario->channels(); }
    double nominalSampleRate_hz() const override { return m_scenario->sampleRate_hz(); }
    ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override;
    // Its strain channels' bridges switch a shunt as a TSP/1 probe's do
    // (ShuntedBridges.h), and it answers as one would.
    std::optional<std::string> requestShunt(std::size_t channel, bool on) override;
    std::vector<DeviceStatus> takeStatuses() override;
    // Paced in real time it times its samples by the host's clock itself:
    // sample k is taken at the pace's start + (k + 1)·dt/speed (when its
    // block is due). Exact; none before the first block, or unpaced.
    std::optional<core::timing::ClockMapping> hostClock() const override;

private:
    mutable std::mutex m_shuntMutex;  // guards the two below: the owner switches, the reader applies
    ShuntedBridges m_shunts;
    std::vector<DeviceStatus> m_statuses;
    std::unique_ptr<SimulatedScenario> m_scenario;
    SimulatorOptions m_options;
    std::optional<std::uint64_t> m_totalSamples;
    std::uint64_t m_produced = 0;
    std::uint32_t m_sequence = 0;
    std::optional<std::chrono::steady_clock::time_point> m_start;
    std::atomic<double> m_start_host_s = std::numeric_limits<double>::quiet_NaN();  // m_start, for any thread
};

}  // namespace tactiscope::devices::simulator
