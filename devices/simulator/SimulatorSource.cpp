// SimulatorSource: pacing and block framing of a simulated scenario.
#include "devices/simulator/SimulatorSource.h"

#include "core/SampleBlock.h"
#include "core/Version.h"
#include "devices/simulator/ClockMark.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <utility>

namespace tactiscope::devices::simulator {

SimulatorSource::SimulatorSource(std::unique_ptr<SimulatedScenario> scenario, const SimulatorOptions& options)
    : m_shunts(scenario ? scenario->channels() : std::vector<core::ChannelDescriptor>{}),
      m_scenario(std::move(scenario)),
      m_options(options)
{
    if (!m_scenario) throw std::invalid_argument("simulator needs a scenario");
    if (m_options.samplesPerBlock == 0) throw std::invalid_argument("simulator needs at least one sample per block");
    if (!(m_options.speed > 0.0)) throw std::invalid_argument("simulator speed must be positive");
    if (m_options.markAt_s && m_options.pacing != Pacing::RealTime)
        throw std::invalid_argument(
            "a simulator's clock mark needs real-time pacing: unpaced, no host instant is known");
    if (m_options.duration_s) {
        if (!(*m_options.duration_s >= 0.0)) throw std::invalid_argument("simulation duration must not be negative");
        m_totalSamples = static_cast<std::uint64_t>(std::llround(*m_options.duration_s * m_scenario->sampleRate_hz()));
    }
}

std::string SimulatorSource::name() const
{
    return "Simulator — " + m_scenario->name();
}

DeviceIdentity SimulatorSource::identity() const
{
    return {"Tactiscope simulator", m_scenario->name(), core::versionString()};
}

ReadStatus SimulatorSource::readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout)
{
    constexpr double kLongestBlock_s = 0.02;
    const auto withinLongest =
        static_cast<std::size_t>(std::max(1.0, std::floor(kLongestBlock_s * m_scenario->sampleRate_hz())));
    std::size_t count = std::min(m_options.samplesPerBlock, withinLongest);
    if (m_totalSamples) {
        if (m_produced >= *m_totalSamples) return ReadStatus::Finished;
        count = static_cast<std::size_t>(std::min<std::uint64_t>(count, *m_totalSamples - m_produced));
    }
    const double dt_s = 1.0 / m_scenario->sampleRate_hz();

    if (m_options.pacing == Pacing::RealTime) {
        const auto now = std::chrono::steady_clock::now();
        if (!m_start) {
            m_start = now;
            m_start_host_s = std::chrono::duration<double>(now.time_since_epoch()).count();
        }
        const auto ready =
            *m_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(
                           static_cast<double>(m_produced + count) * dt_s / m_options.speed));
        if (ready > now + timeout) {
            std::this_thread::sleep_for(timeout);
            return ReadStatus::Timeout;
        }
        std::this_thread::sleep_until(ready);
    }

    out = core::SampleBlock(m_scenario->channels().size(), count, static_cast<double>(m_produced) * dt_s, dt_s,
                            m_produced, m_sequence++);
    m_scenario->generate(out);
    if (m_options.markAt_s) {
        // By the instants its mapping states: one definition of when a sample is taken.
        const auto clock = hostClock();
        simulator::addClockMark(out, *m_options.markAt_s, m_scenario->sampleRate_hz(),
                                [&](std::uint64_t k) { return clock->host_s(static_cast<double>(k) * dt_s); });
    }
    {
        const std::lock_guard lock(m_shuntMutex);
        m_shunts.apply(out);
    }
    m_produced += count;
    return ReadStatus::Block;
}

std::optional<std::string> SimulatorSource::requestShunt(std::size_t channel, bool on)
{
    const std::lock_guard lock(m_shuntMutex);
    const auto refusal = m_shunts.set(channel, on);
    const std::string name = channel < channels().size() ? channels()[channel].name : std::string("?");
    m_statuses.push_back(refusal ? DeviceStatus{2, "shunt: " + *refusal}
                                 : DeviceStatus{0, std::string(on ? "shunt on " : "shunt off ") + name});
    return std::nullopt;
}

std::vector<DeviceStatus> SimulatorSource::takeStatuses()
{
    const std::lock_guard lock(m_shuntMutex);
    return std::exchange(m_statuses, {});
}

std::optional<core::timing::ClockMapping> SimulatorSource::hostClock() const
{
    const double start_s = m_start_host_s;
    if (std::isnan(start_s)) return std::nullopt;
    core::timing::ClockMapping mapping;
    mapping.offset_s = start_s + 1.0 / m_scenario->sampleRate_hz() / m_options.speed;
    mapping.drift = 1.0 / m_options.speed - 1.0;
    mapping.basis = core::timing::ClockUncertaintyBasis::Exact;
    return mapping;
}

}  // namespace tactiscope::devices::simulator
