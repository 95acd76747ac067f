// LiveCapacitive: the readout per sample, the start tare and the display block.
#include "core/capacitive/LiveCapacitive.h"

#include "core/ModeCapability.h"
#include "core/SampleBlock.h"
#include "core/text/JsonWriter.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::capacitive {
namespace {

std::size_t capacitanceChannel(const std::vector<ChannelDescriptor>& channels)
{
    if (const auto picked = modeChannels(Mode::Capacitive, channels)) return picked->front();
    throw std::invalid_argument(*modeRefusal(Mode::Capacitive, channels));
}

}  // namespace

std::string baselineJson(double c0_f)
{
    text::JsonWriter json;
    json.beginObject().key("c0_f").value(c0_f).endObject();
    return json.str();
}

std::optional<double> baselineFromJson(const std::string& text)
{
    const auto json = nlohmann::json::parse(text, nullptr, false);
    if (!json.is_object() || !json.contains("c0_f") || !json["c0_f"].is_number()) return std::nullopt;
    const double c0_f = json["c0_f"].get<double>();
    return std::isfinite(c0_f) && c0_f > 0.0 ? std::optional(c0_f) : std::nullopt;
}

ReadoutSettings readoutSettings(const sensors::CapacitiveBeamProfile& probe,
                                std::span<const calibration::CalibrationRecord> calibrations,
                                std::optional<std::size_t>* used, std::string* problem)
{
    const sensors::CapacitiveBeam beam(probe.geometry);
    ReadoutSettings settings{CapacitiveSensitivity::fromModel(beam), {}};
    std::optional<std::size_t> newest;
    for (std::size_t i = 0; i < calibrations.size(); ++i) {
        const auto& record = calibrations[i];
        if (record.kind != calibration::kCapacitiveKind || record.sensorName != probe.name) continue;
        if (!newest || record.timestampUtc >= calibrations[*newest].timestampUtc) newest = i;
    }
    if (!newest) return settings;
    try {
        const auto stored = capacitiveCalibrationOf(calibrations[*newest], beam);
        settings.sensitivity = stored.sensitivity;
        settings.drift.noiseSigma_f = stored.noiseSigma_f;
        if (used) *used = newest;
    } catch (const std::invalid_argument& e) {
        if (problem)
            *problem = "the newest capacitive calibration of '" + probe.name +
                       "' cannot be used (the beam model is used instead): " + e.what();
    }
    return settings;
}

StoredCapacitiveCalibration capacitiveCalibrationOf(const calibration::CalibrationRecord& record,
                                                    const sensors::CapacitiveBeam& beam)
{
    const auto c0 = record.value("c0_pf");
    const auto perMilliNewton = record.value("sensitivity_pf_per_mn");
    const auto perMillimetre = record.value("displacement_sensitivity_pf_per_mm");
    if (record.kind != calibration::kCapacitiveKind || !c0 || (!perMilliNewton && !perMillimetre))
        throw std::invalid_argument("not a capacitive calibration with C0 and a sensitivity");
    // pF per mN = 1e-12 F / 1e-3 N: ×1e-9 to F/N; likewise pF per mm to F/m.
    const double k = beam.stiffness_n_per_m();
    CapacitiveSensitivity s{*c0 * 1e-12, 0.0, 0.0};
    s.perNewton_f = perMilliNewton ? *perMilliNewton * 1e-9 : *perMillimetre * 1e-9 / k;
    s.perMetre_f = perMillimetre ? *perMillimetre * 1e-9 : *perMilliNewton * 1e-9 * k;
    return {s, record.value("baseline_sigma_pf").value_or(0.0) * 1e-12};
}

LiveCapacitive::LiveCapacitive(const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                               const CapacitiveSensitivity& sensitivity, const DriftSettings& drift,
                               double displaySeconds, const sensors::ChannelScales& scales)
    : m_channel(capacitanceChannel(channels)),
      m_input(capacitanceInput(channels[m_channel], scales)),
      m_output(std::make_shared<LiveBuffer>(outputChannels().size(),
                                            static_cast<std::size_t>(std::ceil(displaySeconds * sampleRate_hz)) + 1)),
      m_noiseSigma_f(drift.noiseSigma_f),
      m_window(std::max<std::size_t>(4, static_cast<std::size_t>(std::lround(kTare_s * sampleRate_hz)))),
      m_baseline{0, sensitivity.c0_f},
      m_readout(sensitivity, drift)
{
}

std::optional<std::string> LiveCapacitive::tare()
{
    const std::lock_guard lock(m_mutex);
    if (!m_window.full()) return "wait half a second: the signal is too short to judge";
    const double shift_f = m_window.halfShift();
    if (!windowSteady()) {
        char change[32];
        std::snprintf(change, sizeof change, "%.3f", shift_f * 1e12);
        return std::string("the capacitance is changing (") + change +
               " pF within half a second): wait until the load is placed or lifted and the signal settles";
    }
    m_pendingC0_f = m_window.mean();
    return std::nullopt;
}

// Not a load being placed or lifted: no step within the last kTare_s
// beyond its noise, or its halves within 3σ of the calibrated baseline noise.
bool LiveCapacitive::windowSteady() const
{
    return m_window.stepScore() <= kSteadyScore || std::abs(m_window.halfShift()) <= 3.0 * m_noiseSigma_f;
}

void LiveCapacitive::inheritBaseline(const LiveCapacitive& previous)
{
    const BaselineChange baseline = previous.currentBaseline();
    {
        const std::lock_guard lock(previous.m_mutex);
        if (!previous.m_startTaredSeen) return;  // it had not taken one yet: this one will
    }
    m_readout.setBaseline(baseline.c0_f);
    m_changesSeen = m_readout.baselineChanges();
    m_startTared = true;
    const std::lock_guard lock(m_mutex);
    m_baseline = baseline;
    m_startTaredSeen = true;
}

std::vector<ChannelDescriptor> LiveCapacitive::outputChannels()
{
    return {{"F", "N", ChannelKind::Force}, {"w", "m", ChannelKind::Position}};
}

void LiveCapacitive::consume(const SampleBlock& block)
{
    if (block.empty()) return;
    std::vector<BaselineChange> changes;
    {
        const std::lock_guard lock(m_mutex);
        if (const auto c0 = std::exchange(m_pendingC0_f, std::nullopt)) m_readout.setBaseline(*c0);
    }
    SampleBlock display(2, block.sampleCount(), block.t0_s(), block.dt_s(), block.firstSampleIndex(), block.sequence());
    CapacitiveReading reading;
    std::size_t windowed = 0;  // of this block's samples, those already in the window
    for (std::size_t s = 0; s < block.sampleCount(); ++s) {
        const double c_f = m_input.farads(block.value(m_channel, s));
        if (!m_startTared) {
            // The start's C0: the first kTare_s of the stream that is
            // steady, read from the sample after it on.
            const std::lock_guard lock(m_mutex);
            if (m_window.full() && windowSteady()) {
                m_readout.setBaseline(m_window.mean());
                m_startTared = true;
            }
            m_window.push(c_f);
            windowed = s + 1;
        }
        reading = m_readout.push(block.timeAt_s(s), c_f);
        // A new C0 (a tare before this sample, a drift step at it) reads this sample on.
        if (m_readout.baselineChanges() != m_changesSeen) {
            m_changesSeen = m_readout.baselineChanges();
            changes.push_back({block.firstSampleIndex() + s, m_readout.c0_f()});
        }
        display.channel(0)[s] = reading.force_n;
        display.channel(1)[s] = reading.displacement_m;
    }
    m_output->consume(display);
    const std::lock_guard lock(m_mutex);
    if (!changes.empty()) m_baseline = changes.back();
    m_startTaredSeen = m_startTared;
    m_baselineChanges.insert(m_baselineChanges.end(), changes.begin(), changes.end());
    m_latest = reading;
    for (std::size_t s = windowed; s < block.sampleCount(); ++s)
        m_window.push(m_input.farads(block.value(m_channel, s)));
}

BaselineChange LiveCapacitive::currentBaseline() const
{
    const std::lock_guard lock(m_mutex);
    return m_baseline;
}

std::vector<BaselineChange> LiveCapacitive::takeBaselineChanges()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_baselineChanges, {});
}

std::optional<CapacitiveReading> LiveCapacitive::latest() const
{
    const std::lock_guard lock(m_mutex);
    return m_latest;
}

}  // namespace tactiscope::core::capacitive
