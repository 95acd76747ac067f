// A probe behind a pseudo-terminal: anyone can try the serial path without
// hardware, and the tests use it. It creates a pty, puts a symlink at the
// requested path, and behaves like firmware behind it: TSP/1 (answers
// request-info, obeys start/stop/set-rate/tare; streams only after start) or
// Serial-Plotter text (streams at once). Samples come from a simulator
// scenario in real time; optionally it injects corrupt bytes, and counts
// what it injected so tests can compare, or misbehaves as broken firmware
// does (EmulatorFault) so the host's checks can be tried.
//
// A device with no reader behaves like a UART with nobody listening: frames
// that cannot be written within 50 ms are dropped (and counted).
#pragma once

#include "core/detector/FirmwarePairDetector.h"
#include "devices/PortSource.h"
#include "devices/protocol/BinaryDecoder.h"
#include "devices/simulator/MainsHumOverlay.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/ShuntedBridges.h"
#include "devices/simulator/SimulatedScenario.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>

namespace tactiscope::devices::emulator {

// Firmware faults, for TSP/1: a restart (the probe stops for half a second,
// then its sequence and clock begin again at 0), one frame whose sequence
// jumps by 30 000, a sequence that never moves from 0, or (with the probe's
// detector on) a detector built wrong: it takes its gauges for face to
// face, so it names every defect's direction the wrong way round.
enum class EmulatorFault { None, Restart, SequenceJump, FrozenSequence, WrongDecisions };

struct EmulatorOptions {
    std::string linkPath;
    WireProtocol protocol = WireProtocol::Binary;
    std::string scenario = simulator::kPanelScanScenario;
    std::optional<double> rate_hz;
    std::optional<std::size_t> channels;  // fewer: the first N; more: repeated
    std::optional<double> seconds;        // stream this long, then hang up
    double garbageRate = 0.0;             // fraction of frames with garbage
    std::size_t samplesPerFrame = 10;
    std::uint64_t seed = 1;
    simulator::MainsHumSettings hum = {};              // none unless set
    std::optional<double> infoRate_hz = std::nullopt;  // the rate its INFO claims (a lie when not the true rate)
    EmulatorFault fault = EmulatorFault::None;
    double faultAt_s = 3.0;  // stream time of a restart or a jump
    // The rate its clock stamps frames at (default: the true rate; another
    // is a clock that lies with its INFO).
    std::optional<double> clockRate_hz = std::nullopt;
    // Its crystal: host seconds per device second, less one (+80e-6: its
    // clock runs 80 ppm slow, and it samples as much slower in host time),
    // and its clock's reading at the first sample, in seconds. Two
    // emulators with known values are two devices to align (issue 40).
    double clockDrift = 0.0;
    double clockOffset_s = 0.0;
    // A mark at this instant of the host's steady clock (CLOCK_MONOTONIC,
    // seconds; devices/simulator/ClockMark.h). Two emulators given one
    // instant mark one event, to see aligned in the session (issue 40).
    std::optional<double> markAt_s = std::nullopt;
    // A calibration sweep (devices/simulator/LoadSweep.h) begun at this
    // instant of the host's steady clock, pushed through the scenario's
    // load rig by the host instant each sample is taken at: a capacitive
    // beam (capacitive-calibration) and a load cell (load-cell) emulated
    // with one instant feel one force (issue 40).
    std::optional<double> sweepAt_s = std::nullopt;
    // The probe runs the detector itself (firmware/probe-detector) on its
    // cantilevers and sends its decision and best R each way as channels
    // of kind "decision" named out, rab and rba (panel scan, TSP/1).
    bool probeDetector = false;
    // Its strain channels' bridges can switch a shunt (TSP/1 command 6,
    // devices/simulator/ShuntedBridges.h); false: an older probe that
    // answers nothing to the command.
    bool shunt = true;
};

// "restart@3", "sequence-jump@2.5", "frozen-sequence", "wrong-decisions": the command line's
// words for a fault; none for anything else.
std::optional<std::pair<EmulatorFault, double>> parseFault(const std::string& text);

struct EmulatorStats {
    std::uint64_t framesSent = 0;       // data frames or lines written whole
    std::uint64_t samplesSent = 0;      // per channel, in frames written whole and intact
    std::uint64_t garbageBursts = 0;    // random bytes inserted between frames
    std::uint64_t corruptedFrames = 0;  // frames with a flipped byte
    std::uint64_t droppedFrames = 0;    // nobody reading
    std::uint64_t commands = 0;
};

class ProbeEmulator {
public:
    // Creates the pty and the symlink (replacing an old symlink there).
    // Throws std::runtime_error on failure or std::invalid_argument for bad
    // options (unknown scenario, …).
    explicit ProbeEmulator(const EmulatorOptions& options);
    ~ProbeEmulator();  // stops, hangs up, removes the symlink

    ProbeEmulator(const ProbeEmulator&) = delete;
    ProbeEmulator& operator=(const ProbeEmulator&) = delete;

    void start();
    // Hangs up: the reader sees the device disconnect.
    void stop();
    bool finished() const { return m_finished; }
    const std::string& ptyPath() const { return m_ptyPath; }
    EmulatorStats stats() const;

private:
    void run(const std::stop_token& stop);
    void handleCommands();
    void sendFrame(std::vector<std::uint8_t> frame, std::size_t samples);
    bool writeAll(const std::vector<std::uint8_t>& bytes);
    std::vector<std::uint8_t> nextPayload(std::size_t& samples);
    // The host instant (steady clock, s) sample `index` is taken at.
    double takenAt_s(std::uint64_t index) const;
    void addMark(core::SampleBlock& block) const;
    void generate(core::SampleBlock& block);
    void hangUp();

    EmulatorOptions m_options;
    std::unique_ptr<simulator::SimulatedScenario> m_scenario;
    std::optional<simulator::ShuntedBridges> m_shunts;  // on the scenario's own channels
    std::vector<core::ChannelDescriptor> m_channels;
    double m_rate_hz = 0.0;
    int m_master = -1;
    int m_slave = -1;
    std::string m_ptyPath;
    std::mt19937_64 m_random;
    std::atomic<bool> m_streaming = false;
    std::atomic<bool> m_finished = false;
    std::uint16_t m_sequence = 0;
    std::uint64_t m_sampleIndex = 0;
    std::uint64_t m_streamStartIndex = 0;  // m_sampleIndex when the stream (re)started pacing
    std::chrono::steady_clock::time_point m_streamStart{};
    std::uint64_t m_clockStart = 0;                                  // the sample index the device clock counts from
    bool m_faulted = false;                                          // a one-off fault has happened
    std::optional<core::detector::FirmwarePairDetector> m_detector;  // the probe's own, when it runs one
    std::vector<core::detector::DetectorOutput> m_decisions;         // one frame's
    protocol::BinaryDecoder m_commandDecoder;                        // host → device commands
    mutable std::mutex m_statsMutex;
    EmulatorStats m_stats;
    std::jthread m_thread;
};

}  // namespace tactiscope::devices::emulator
