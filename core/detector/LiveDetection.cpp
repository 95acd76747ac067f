// LiveDetection: engine swap between blocks, output block per input block.
#include "core/detector/LiveDetection.h"

#include "core/SampleBlock.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::detector {
namespace {

// How far back the position trail reaches: an event completes a hold
// after its last sample, and its crossing lies before its middle.
constexpr double kTrail_s = 30.0;

}  // namespace

LiveDetection::LiveDetection(std::vector<std::size_t> cantileverChannels, double sampleRate_hz,
                             LiveDetectionSettings settings, double displaySeconds,
                             std::optional<ProbeDecisionChannels> probe, std::optional<std::size_t> position)
    : m_channels(std::move(cantileverChannels)),
      m_positionChannel(position),
      m_sampleInterval_s(1.0 / sampleRate_hz),
      m_output(std::make_shared<LiveBuffer>(3, static_cast<std::size_t>(std::ceil(displaySeconds * sampleRate_hz)) + 1))
{
    settings.parameters.sampleInterval_s = m_sampleInterval_s;
    m_engine = makeEngine(settings);
    if (probe) {
        m_probe.emplace(*probe, m_sampleInterval_s, settings.hold_s, settings.spacing_m);
        m_agreement = ProbeAgreement{};
    }
    // Long enough to reach from an event's completion back to its crossing.
    if (position) m_trail.emplace(static_cast<std::size_t>(std::ceil(kTrail_s * sampleRate_hz)), m_sampleInterval_s);
    m_settings = std::move(settings);
}

std::vector<ChannelDescriptor> LiveDetection::outputChannels()
{
    return {{"decision", "", ChannelKind::Other}, {"R A→B", "", ChannelKind::Other}, {"R B→A", "", ChannelKind::Other}};
}

std::unique_ptr<LiveDetection::Engine> LiveDetection::makeEngine(const LiveDetectionSettings& settings) const
{
    return std::make_unique<Engine>(
        Engine{ProbeDetector(settings.parameters, m_channels), EventSegmenter(settings.hold_s, settings.spacing_m)});
}

void LiveDetection::setSettings(LiveDetectionSettings settings)
{
    settings.parameters.sampleInterval_s = m_sampleInterval_s;
    auto engine = makeEngine(settings);  // throws before anything changes
    const std::lock_guard lock(m_mutex);
    m_pending = std::move(engine);
    m_settings = std::move(settings);
}

LiveDetectionSettings LiveDetection::settings() const
{
    const std::lock_guard lock(m_mutex);
    return m_settings;
}

void LiveDetection::consume(const SampleBlock& block)
{
    if (block.empty()) return;
    {
        const std::lock_guard lock(m_mutex);
        if (m_pending) {
            m_engine->segmenter.finish(m_completed);  // an open event ends with its settings
            m_engine = std::move(m_pending);
        }
    }
    if (m_nextIndex && block.firstSampleIndex() != *m_nextIndex) {
        m_engine->segmenter.finish(m_completed);
        m_engine->detector.reset();
        m_engine->segmenter.reset();
        if (m_probe) m_probe->restart(m_probeCompleted);
    }
    m_nextIndex = block.endSampleIndex();
    if (m_trail)
        for (std::size_t s = 0; s < block.sampleCount(); ++s)
            m_trail->push(block.timeAt_s(s), block.channel(*m_positionChannel)[s]);
    const auto outputs = m_engine->detector.push(block);
    SampleBlock display(3, outputs.size(), block.t0_s(), block.dt_s(), block.firstSampleIndex(), block.sequence());
    for (std::size_t s = 0; s < outputs.size(); ++s) {
        const auto& o = outputs[s].combined;
        display.channel(0)[s] = o.decision;
        display.channel(1)[s] = o.rab;
        display.channel(2)[s] = o.rba;
        m_engine->segmenter.push(block.timeAt_s(s), o, m_sampleInterval_s, m_completed);
        if (m_probe) m_probe->push(block, s, o, m_probeCompleted, m_disagreed);
    }
    m_output->consume(display);
    if (m_trail) m_trail->stamp(m_completed);
    const std::lock_guard lock(m_mutex);
    m_events.insert(m_events.end(), m_completed.begin(), m_completed.end());
    m_completed.clear();
    if (!m_probe) return;
    m_probeEvents.insert(m_probeEvents.end(), m_probeCompleted.begin(), m_probeCompleted.end());
    m_probeCompleted.clear();
    m_disagreements.insert(m_disagreements.end(), m_disagreed.begin(), m_disagreed.end());
    m_disagreed.clear();
    m_agreement = m_probe->agreement();
}

std::vector<DefectEvent> LiveDetection::takeEvents()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_events, {});
}

std::vector<DefectEvent> LiveDetection::takeProbeEvents()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_probeEvents, {});
}

std::vector<ProbeDisagreement> LiveDetection::takeDisagreements()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_disagreements, {});
}

std::optional<ProbeAgreement> LiveDetection::probeAgreement() const
{
    const std::lock_guard lock(m_mutex);
    return m_agreement;
}

}  // namespace tactiscope::core::detector
