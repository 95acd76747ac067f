// ProbeEmulator: pty, symlink, command handling and paced streaming.
#include "devices/emulator/ProbeEmulator.h"

#include "core/SampleBlock.h"
#include "core/Version.h"
#include "devices/protocol/BinaryDecoder.h"
#include "devices/simulator/ClockMark.h"
#include "devices/simulator/LoadSweep.h"
#include "devices/simulator/ScenarioCatalog.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <pty.h>
#include <stdexcept>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

namespace tactiscope::devices::emulator {
namespace {

// The probe detector's channels: out, rab, rba, lag_ab, lag_ba.
constexpr std::size_t kDecisionChannels = 5;

using Clock = std::chrono::steady_clock;

// How long a restarting probe is silent.
constexpr std::chrono::milliseconds kRestartPause(500);
// How far past --seconds a stream that lagged (a reader too slow, a restart
// pause) may run to send what it owes.
constexpr double kLateGrace_s = 0.25;

}  // namespace

std::optional<std::pair<EmulatorFault, double>> parseFault(const std::string& text)
{
    if (text == "frozen-sequence") return std::pair(EmulatorFault::FrozenSequence, 0.0);
    if (text == "wrong-decisions") return std::pair(EmulatorFault::WrongDecisions, 0.0);
    const auto at = text.find('@');
    if (at == std::string::npos) return std::nullopt;
    const std::string kind = text.substr(0, at), when = text.substr(at + 1);
    char* end = nullptr;
    const double seconds = std::strtod(when.c_str(), &end);
    if (when.empty() || *end != '\0' || !std::isfinite(seconds) || seconds < 0.0) return std::nullopt;
    if (kind == "restart") return std::pair(EmulatorFault::Restart, seconds);
    if (kind == "sequence-jump") return std::pair(EmulatorFault::SequenceJump, seconds);
    return std::nullopt;
}

ProbeEmulator::ProbeEmulator(const EmulatorOptions& options)
    : m_options(options),
      m_random(options.seed)
{
    m_scenario = simulator::makeScenario(options.scenario, options.seed, options.rate_hz);
    if (!m_scenario) throw std::invalid_argument("unknown scenario '" + options.scenario + "'");
    if (options.hum.any()) m_scenario = std::make_unique<simulator::HummedScenario>(std::move(m_scenario), options.hum);
    if (options.samplesPerFrame == 0 || options.samplesPerFrame > 1000)
        throw std::invalid_argument("samples per frame must be 1 to 1000");
    if (!(options.garbageRate >= 0.0 && options.garbageRate <= 1.0))
        throw std::invalid_argument("garbage rate must lie between 0 and 1");
    if (options.fault != EmulatorFault::None && options.protocol != WireProtocol::Binary)
        throw std::invalid_argument("firmware faults are emulated on TSP/1 (binary) only");
    m_rate_hz = m_scenario->sampleRate_hz();
    const auto& base = m_scenario->channels();
    const std::size_t count = options.channels.value_or(base.size());
    if (count == 0 || count > 64) throw std::invalid_argument("channels must be 1 to 64");
    for (std::size_t i = 0; i < count; ++i) {
        core::ChannelDescriptor c = base[i % base.size()];
        if (i >= base.size()) c.name += std::to_string(i / base.size() + 1);
        m_channels.push_back(c);
    }
    m_shunts.emplace(base);
    if (options.sweepAt_s && !m_scenario->loadRig())
        throw std::invalid_argument("a sweep needs a scenario with a load rig (capacitive-calibration, load-cell)");
    if (options.fault == EmulatorFault::WrongDecisions && !options.probeDetector)
        throw std::invalid_argument("wrong decisions need the probe's detector on");
    if (options.probeDetector) {
        if (options.scenario != simulator::kPanelScanScenario || options.protocol != WireProtocol::Binary)
            throw std::invalid_argument("the probe's detector runs on a panel scan over TSP/1 (binary)");
        // The paper's settings at this rate, as the workstation's live detector takes them.
        core::detector::DetectorParameters parameters;
        parameters.sampleInterval_s = 1.0 / m_rate_hz;
        parameters.lags_s = core::detector::liveLags_s(m_rate_hz);
        parameters.faceToFace = options.fault == EmulatorFault::WrongDecisions;
        m_detector.emplace(parameters);  // throws std::invalid_argument for a rate it cannot run at
        for (const char* name : {"out", "rab", "rba"}) m_channels.push_back({name, "", core::ChannelKind::Decision});
        for (const char* name : {"lag_ab", "lag_ba"}) m_channels.push_back({name, "s", core::ChannelKind::Decision});
    }

    if (::openpty(&m_master, &m_slave, nullptr, nullptr, nullptr) != 0)
        throw std::runtime_error(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
    termios tty{};
    ::tcgetattr(m_slave, &tty);
    ::cfmakeraw(&tty);
    ::tcsetattr(m_slave, TCSANOW, &tty);
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    m_ptyPath = ::ttyname(m_slave);

    namespace fs = std::filesystem;
    const fs::path link(options.linkPath);
    std::error_code error;
    if (fs::is_symlink(fs::symlink_status(link, error))) {
        fs::remove(link, error);
    } else if (fs::exists(fs::symlink_status(link, error))) {
        hangUp();
        throw std::runtime_error("refusing to replace " + options.linkPath + ": it exists and is not a symlink");
    }
    fs::create_symlink(m_ptyPath, link, error);
    if (error) {
        hangUp();
        throw std::runtime_error("cannot create the link " + options.linkPath + ": " + error.message());
    }
    m_streaming = options.protocol == WireProtocol::Text;  // text boards just print
}

ProbeEmulator::~ProbeEmulator()
{
    stop();
    std::error_code error;
    if (std::filesystem::read_symlink(m_options.linkPath, error) == m_ptyPath)
        std::filesystem::remove(m_options.linkPath, error);
}

void ProbeEmulator::start()
{
    if (!m_thread.joinable() && !m_finished) m_thread = std::jthread([this](const std::stop_token& s) { run(s); });
}

void ProbeEmulator::stop()
{
    if (m_thread.joinable()) {
        m_thread.request_stop();
        m_thread.join();
    }
    hangUp();
}

void ProbeEmulator::hangUp()
{
    // Marked first, so a reader that sees the hang-up also sees finished().
    m_finished = true;
    if (m_master >= 0) ::close(m_master);
    if (m_slave >= 0) ::close(m_slave);
    m_master = m_slave = -1;
}

EmulatorStats ProbeEmulator::stats() const
{
    const std::lock_guard lock(m_statsMutex);
    return m_stats;
}

bool ProbeEmulator::writeAll(const std::vector<std::uint8_t>& bytes)
{
    std::size_t done = 0;
    const auto deadline = Clock::now() + std::chrono::milliseconds(50);
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_master, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
        } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
            return false;
        } else {
            if (Clock::now() >= deadline) return false;
            pollfd p{m_master, POLLOUT, 0};
            ::poll(&p, 1, 5);
        }
    }
    return true;
}

void ProbeEmulator::sendFrame(std::vector<std::uint8_t> frame, std::size_t samples)
{
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    bool corrupted = false, burst = false;
    std::vector<std::uint8_t> bytes;
    if (m_options.garbageRate > 0.0 && chance(m_random) < m_options.garbageRate) {
        if (chance(m_random) < 0.5) {
            // Random bytes between frames. They never contain the sync's first
            // byte (or a newline in text), so each burst is one clean resync.
            burst = true;
            const std::size_t n = 1 + m_random() % 16;
            for (std::size_t i = 0; i < n; ++i) {
                std::uint8_t b = static_cast<std::uint8_t>(m_random());
                if (b == protocol::kSync0 || b == '\n') b = 0x3F;
                bytes.push_back(b);
            }
        } else if (m_options.protocol == WireProtocol::Binary &&
                   frame.size() > protocol::kHeaderSize + protocol::kCrcSize) {
            // Flip one payload byte: exactly one CRC error at the host.
            corrupted = true;
            const std::size_t payload = frame.size() - protocol::kHeaderSize - protocol::kCrcSize;
            frame[protocol::kHeaderSize + m_random() % payload] ^= static_cast<std::uint8_t>(1 + m_random() % 255);
        } else if (m_options.protocol == WireProtocol::Text && frame.size() > 1) {
            corrupted = true;
            frame[m_random() % (frame.size() - 1)] = '#';  // never the newline
        }
    }
    bytes.insert(bytes.end(), frame.begin(), frame.end());
    const bool written = writeAll(bytes);
    const std::lock_guard lock(m_statsMutex);
    if (!written) {
        ++m_stats.droppedFrames;
        return;
    }
    ++m_stats.framesSent;
    m_stats.garbageBursts += burst;
    m_stats.corruptedFrames += corrupted;
    if (!corrupted) m_stats.samplesSent += samples;
}

// The stream's start plus its samples since, at the crystal's pace.
double ProbeEmulator::takenAt_s(std::uint64_t index) const
{
    const double start_s = std::chrono::duration<double>(m_streamStart.time_since_epoch()).count();
    return start_s + static_cast<double>(index - m_streamStartIndex) / m_rate_hz * (1.0 + m_options.clockDrift);
}

void ProbeEmulator::addMark(core::SampleBlock& block) const
{
    if (m_options.markAt_s)
        simulator::addClockMark(block, *m_options.markAt_s, m_rate_hz,
                                [this](std::uint64_t index) { return takenAt_s(index); });
}

// The scenario's samples; under a sweep one at a time, each with the load
// of the instant it is taken at on the rig.
void ProbeEmulator::generate(core::SampleBlock& block)
{
    if (!m_options.sweepAt_s) return m_scenario->generate(block);
    const simulator::LoadSweep sweep;
    const std::shared_ptr<simulator::LoadRig> rig = m_scenario->loadRig();
    core::SampleBlock one(block.channelCount(), 1, 0.0, 1.0 / m_rate_hz, 0);
    for (std::size_t s = 0; s < block.sampleCount(); ++s) {
        rig->place(sweep.load_n(takenAt_s(block.firstSampleIndex() + s) - *m_options.sweepAt_s));
        m_scenario->generate(one);
        for (std::size_t c = 0; c < block.channelCount(); ++c) block.channel(c)[s] = one.channel(c)[0];
    }
}

std::vector<std::uint8_t> ProbeEmulator::nextPayload(std::size_t& samples)
{
    const std::size_t n = m_options.samplesPerFrame;
    const std::size_t baseChannels = m_scenario->channels().size();
    core::SampleBlock block(baseChannels, n, static_cast<double>(m_sampleIndex) / m_rate_hz, 1.0 / m_rate_hz,
                            m_sampleIndex);
    generate(block);
    m_shunts->apply(block);
    addMark(block);
    samples = n;
    if (m_options.protocol == WireProtocol::Text) {
        std::string text;
        char number[32];
        for (std::size_t s = 0; s < n; ++s) {
            for (std::size_t c = 0; c < m_channels.size(); ++c) {
                std::snprintf(number, sizeof number, "%.9g", block.value(c % baseChannels, s));
                text += (c ? " " : "") + m_channels[c].name + ":" + number;
            }
            text += '\n';
        }
        m_sampleIndex += n;
        return {text.begin(), text.end()};
    }
    protocol::DataPayload data;
    data.timestamp_us = static_cast<std::uint32_t>(
        std::llround(m_options.clockOffset_s * 1e6 + static_cast<double>(m_sampleIndex - m_clockStart) * 1e6 /
                                                         m_options.clockRate_hz.value_or(m_rate_hz)) &
        0xFFFFFFFF);
    data.format = protocol::SampleFormat::Float32;
    data.channelCount = static_cast<std::uint8_t>(m_channels.size());
    data.samplesPerChannel = static_cast<std::uint16_t>(n);
    // The probe's detector on the very values it sends (float32, as a and b go out).
    if (m_detector) {
        m_decisions.resize(n);
        m_detector->process(block.channel(0), block.channel(1), m_decisions);
    }
    const std::size_t measured = m_channels.size() - (m_detector ? kDecisionChannels : 0);
    for (std::size_t s = 0; s < n; ++s) {
        for (std::size_t c = 0; c < measured; ++c) data.raw.push_back(block.value(c % baseChannels, s));
        if (!m_detector) continue;
        data.raw.push_back(m_decisions[s].decision);
        data.raw.push_back(m_decisions[s].rab);
        data.raw.push_back(m_decisions[s].rba);
        data.raw.push_back(static_cast<double>(m_decisions[s].lagAb) / m_rate_hz);
        data.raw.push_back(static_cast<double>(m_decisions[s].lagBa) / m_rate_hz);
    }
    std::uint16_t sequence = m_sequence++;
    if (m_options.fault == EmulatorFault::FrozenSequence) sequence = 0;
    if (m_options.fault == EmulatorFault::SequenceJump && !m_faulted &&
        static_cast<double>(m_sampleIndex) / m_rate_hz >= m_options.faultAt_s) {
        m_faulted = true;
        sequence = static_cast<std::uint16_t>(sequence + 30000);  // this frame only
    }
    m_sampleIndex += n;
    return protocol::encodeFrame(protocol::FrameType::Data, sequence, protocol::encodeData(data));
}

void ProbeEmulator::handleCommands()
{
    std::uint8_t buffer[512];
    const ssize_t n = ::read(m_master, buffer, sizeof buffer);
    if (n <= 0 || m_options.protocol != WireProtocol::Binary) return;
    std::vector<protocol::Frame> frames;
    m_commandDecoder.push(std::span<const std::uint8_t>(buffer, static_cast<std::size_t>(n)), frames);
    for (const auto& frame : frames) {
        const auto command = protocol::parseCommand(frame.payload);
        if (frame.type != protocol::FrameType::Command || !command) continue;
        {
            const std::lock_guard lock(m_statsMutex);
            ++m_stats.commands;
        }
        switch (command->code) {
        case protocol::CommandCode::RequestInfo: {
            protocol::DeviceInfo info{
                "Tactiscope",
                "Emulator (" + m_options.scenario + ")",
                "EMU-" + std::to_string(m_options.seed),
                core::versionString(),
                static_cast<std::uint32_t>(std::llround(m_options.infoRate_hz.value_or(m_rate_hz) * 1000.0)),
                {}};
            for (const auto& c : m_channels) info.channels.push_back({c, 1.0f, 0.0f});
            writeAll(protocol::encodeFrame(protocol::FrameType::Info, m_sequence++, protocol::encodeInfo(info)));
            break;
        }
        case protocol::CommandCode::Start:
            m_streaming = true;
            break;
        case protocol::CommandCode::Stop:
            m_streaming = false;
            break;
        case protocol::CommandCode::Tare:
            writeAll(protocol::encodeFrame(protocol::FrameType::Status, m_sequence++,
                                           protocol::encodeStatus({protocol::StatusLevel::Ok, "tared"})));
            break;
        case protocol::CommandCode::SetRate:
            writeAll(protocol::encodeFrame(
                protocol::FrameType::Status, m_sequence++,
                protocol::encodeStatus({protocol::StatusLevel::Warning, "the emulator keeps its scenario's rate"})));
            break;
        case protocol::CommandCode::Shunt: {
            if (!m_options.shunt) break;  // an older probe: it knows no such command
            // A repeated channel is its scenario channel again; the decisions have no bridge.
            const std::size_t measured = m_channels.size() - (m_detector ? kDecisionChannels : 0);
            const std::size_t base = m_scenario->channels().size();
            const auto refusal = command->channel < measured
                                     ? m_shunts->set(command->channel % base, command->on)
                                     : std::optional<std::string>("channel " + std::to_string(command->channel + 1) +
                                                                  " has no bridge to shunt");
            const std::string name =
                command->channel < m_channels.size() ? m_channels[command->channel].name : std::string("?");
            writeAll(protocol::encodeFrame(
                protocol::FrameType::Status, m_sequence++,
                protocol::encodeStatus(
                    refusal ? protocol::StatusPayload{protocol::StatusLevel::Error, "shunt: " + *refusal}
                            : protocol::StatusPayload{protocol::StatusLevel::Ok,
                                                      std::string(command->on ? "shunt on " : "shunt off ") + name})));
            break;
        }
        }
    }
}

void ProbeEmulator::run(const std::stop_token& stop)
{
    Clock::time_point streamStart{};
    std::uint64_t paced = 0;  // samples sent since streaming (re)started
    bool wasStreaming = false;
    // --seconds counts wall time from the first start (a host that stops or
    // hangs up early, or writes that block, do not stretch it), or from
    // launch while nobody has started the stream.
    const auto launched = Clock::now();
    std::optional<Clock::time_point> firstStart;
    const auto timeIsUp = [&] {
        if (!m_options.seconds) return false;
        const std::chrono::duration<double> since = Clock::now() - firstStart.value_or(launched);
        // All samples sent, or the time past with a short grace for a stream that lagged.
        return (firstStart && static_cast<double>(paced) / m_rate_hz >= *m_options.seconds - 1e-9) ||
               since.count() >= *m_options.seconds + (firstStart ? kLateGrace_s : 0.0);
    };
    while (!stop.stop_requested() && !timeIsUp()) {
        handleCommands();
        if (m_streaming && !wasStreaming) {
            streamStart = Clock::now();
            m_streamStart = streamStart;
            m_streamStartIndex = m_sampleIndex;
            if (!firstStart) firstStart = streamStart;
            paced = 0;
        }
        wasStreaming = m_streaming;
        if (!m_streaming) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            continue;
        }
        // Its samples come at its own crystal's pace, and a frame leaves as
        // soon as its last sample is taken (TSP/1: the instant its arrival
        // is paired with; docs/protocol.md).
        const auto due =
            streamStart +
            std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                static_cast<double>(paced + m_options.samplesPerFrame - 1) / m_rate_hz * (1.0 + m_options.clockDrift)));
        if (Clock::now() < due) {
            std::this_thread::sleep_until(std::min(due, Clock::now() + std::chrono::milliseconds(5)));
            continue;
        }
        if (m_options.fault == EmulatorFault::Restart && !m_faulted &&
            static_cast<double>(m_sampleIndex) / m_rate_hz >= m_options.faultAt_s) {
            // The firmware reboots: nothing for a while, then its sequence
            // and clock start again at 0; the world it measures went on.
            m_faulted = true;
            std::this_thread::sleep_for(kRestartPause);
            streamStart += kRestartPause;  // (the sample index jumps the pause too: m_streamStart stays)
            *firstStart += kRestartPause;  // the pause is not streaming time
            m_sampleIndex += static_cast<std::uint64_t>(std::llround(kRestartPause.count() * 1e-3 * m_rate_hz));
            m_clockStart = m_sampleIndex;
            m_options.clockOffset_s = 0.0;  // a clock begun again reads from zero
            m_sequence = 0;
            if (m_detector) m_detector->reset();  // and its detector starts from silence
        }
        std::size_t samples = 0;
        auto payload = nextPayload(samples);
        sendFrame(std::move(payload), samples);
        paced += samples;
    }
    if (m_options.seconds && !stop.stop_requested()) {
        // Like firmware that finishes sending before it disconnects: let the
        // reader take what is in the line (closing the master flushes it).
        // The queue must read empty twice, 10 ms apart: bytes still in the
        // pty's internal buffer are not counted by FIONREAD yet.
        const auto drainDeadline = Clock::now() + std::chrono::milliseconds(500);
        int emptyChecks = 0;
        while (emptyChecks < 2 && Clock::now() < drainDeadline) {
            int pending = 0;
            if (::ioctl(m_slave, FIONREAD, &pending) != 0) break;
            emptyChecks = pending == 0 ? emptyChecks + 1 : 0;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        hangUp();
    }
}

}  // namespace tactiscope::devices::emulator
