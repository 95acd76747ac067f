// PalpationForces: channel roles, a beam's raw value to force, Q and k_o.
#include "core/compliance/PalpationForces.h"

#include "core/ModeCapability.h"
#include "core/UnitScale.h"
#include "core/text/JsonWriter.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tactiscope::core::compliance {
namespace {

BeamInput inputOf(const ChannelDescriptor& channel, const sensors::ChannelScales& scales)
{
    if (isCounts(channel.unit)) return scales.contains(channel.name) ? BeamInput::ProfileScale : BeamInput::GaugeChain;
    return channel.kind == ChannelKind::Force ? BeamInput::Force : BeamInput::Strain;
}

}  // namespace

LivePalpationSettings palpationSettings(const sensors::CompliancePairProfile& probe, double sampleRate_hz,
                                        std::span<const ChannelDescriptor> channels,
                                        std::span<const calibration::CalibrationRecord> calibrations,
                                        std::vector<std::size_t>* used)
{
    LivePalpationSettings settings;
    settings.high = probe.high;
    settings.low = probe.low;
    settings.press = pressSettingsAt(sampleRate_hz);
    settings.scales = probe.channels;
    if (const auto beams = modeChannels(Mode::Palpation, channels)) {
        settings.highInput = inputOf(channels[(*beams)[0]], settings.scales);
        settings.lowInput = inputOf(channels[(*beams)[1]], settings.scales);
    }
    for (const bool stiff : {true, false}) {
        // A gauge factor is used only where the gauge chain is.
        if ((stiff ? settings.highInput : settings.lowInput) != BeamInput::GaugeChain) continue;
        const std::string sensor = calibration::beamSensorName(probe.name, stiff);
        std::optional<std::size_t> newest;
        for (std::size_t i = 0; i < calibrations.size(); ++i) {
            const auto& record = calibrations[i];
            const auto factor = record.value("gauge_factor");
            if (record.kind != calibration::kGaugeFactorKind || record.sensorName != sensor || !factor ||
                !(*factor > 0.0))
                continue;
            if (!newest || record.timestampUtc >= calibrations[*newest].timestampUtc) newest = i;
        }
        if (!newest) continue;
        (stiff ? settings.highGaugeFactor : settings.lowGaugeFactor) = calibrations[*newest].value("gauge_factor");
        if (used) used->push_back(*newest);
    }
    return settings;
}

std::string basisText(const sensors::CompliancePairProfile& probe, const LivePalpationSettings& settings)
{
    const auto beam = [&settings](bool high) {
        const auto& factor = high ? settings.highGaugeFactor : settings.lowGaugeFactor;
        std::ostringstream text;
        switch (high ? settings.highInput : settings.lowInput) {
        case BeamInput::GaugeChain:
            if (factor)
                text << "gauge factor " << *factor << " (calibrated)";
            else
                text << "gauge factor " << settings.bridge.gaugeFactor << " (nominal)";
            break;
        case BeamInput::ProfileScale:
            text << "the profile's scale";
            break;
        case BeamInput::Strain:
            text << "the device's strain";
            break;
        case BeamInput::Force:
            text << "the device's force";
            break;
        }
        return text.str();
    };
    return "profile " + probe.name + "; stiff beam " + beam(true) + ", soft beam " + beam(false);
}

std::optional<std::string> mixedCalibration(const LivePalpationSettings& settings)
{
    if (settings.highGaugeFactor.has_value() == settings.lowGaugeFactor.has_value()) return std::nullopt;
    if (settings.highInput != BeamInput::GaugeChain || settings.lowInput != BeamInput::GaugeChain) return std::nullopt;
    const bool stiff = settings.highGaugeFactor.has_value();
    return std::string("only the ") + (stiff ? "stiff" : "soft") +
           " beam has a gauge-factor calibration: kₒ reads through its calibrated and the " +
           (stiff ? "soft" : "stiff") + " beam's nominal factor, so the nominal one's error is in every reading — " +
           "calibrate the " + (stiff ? "soft" : "stiff") + " beam too";
}

std::string zeroJson(const RawZero& zero)
{
    text::JsonWriter json;
    json.beginObject().key("high").value(zero.high).key("low").value(zero.low);
    if (zero.uncertainty)
        json.key("high_u").value(zero.uncertainty->first).key("low_u").value(zero.uncertainty->second);
    json.endObject();
    return json.str();
}

std::optional<RawZero> zeroFromJson(const std::string& text)
{
    const auto json = nlohmann::json::parse(text, nullptr, false);
    const auto number = [&](const char* key) {
        return json.is_object() && json.contains(key) && json[key].is_number() ? json[key].get<double>()
                                                                               : PalpationForces::kNaN;
    };
    const double high = number("high"), low = number("low");
    if (!std::isfinite(high) || !std::isfinite(low)) return std::nullopt;
    RawZero zero{high, low, std::nullopt};
    const double highU = number("high_u"), lowU = number("low_u");
    if (std::isfinite(highU) && std::isfinite(lowU)) zero.uncertainty = std::pair{highU, lowU};
    return zero;
}

void PalpationForces::Input::setZero(double value)
{
    if (chain)
        chain->tare(value);
    else
        zero = value;
}

double PalpationForces::Input::force(const sensors::CantileverBeam& beam, double value) const
{
    if (chain) return chain->strain(value) / beam.rootStrainPerNewton();
    const double reading = (value - zero) * unitsPerCount;
    if (kind == ChannelKind::Force) return reading;
    return reading / beam.rootStrainPerNewton();  // a strain
}

PalpationForces::PalpationForces(const std::vector<ChannelDescriptor>& channels, const LivePalpationSettings& settings)
    : m_pair(sensors::CantileverBeam(settings.high), sensors::CantileverBeam(settings.low)),
      m_contactThreshold_n(settings.press.contactThreshold_n)
{
    const auto picked = modeChannels(Mode::Palpation, channels);
    if (!picked) throw std::invalid_argument(*modeRefusal(Mode::Palpation, channels));
    const std::vector<std::size_t>& beams = *picked;  // stiff, soft, then the displacement
    m_displacement = beams[2];
    if (isCounts(channels[m_displacement].unit)) {
        const auto scale = settings.scales.find(channels[m_displacement].name);
        const auto unit = scale != settings.scales.end() ? physicalUnit(scale->second.unit) : std::nullopt;
        if (!unit || unit->kind != ChannelKind::Position)
            throw std::invalid_argument("the displacement " + channels[m_displacement].name +
                                        " is in counts and the sensor profile gives it no length scale (\"channels\": "
                                        "{\"" +
                                        channels[m_displacement].name + "\": {\"unit\": \"mm\"}})");
        m_metresPerCount = unit->factor / scale->second.countsPerUnit;
        m_displacementOffset = scale->second.offset_counts;
    }
    const auto input = [&](std::size_t c, std::optional<double> gaugeFactor) {
        Input in;
        in.channel = c;
        in.kind = channels[c].kind;
        const BeamInput how = inputOf(channels[c], settings.scales);
        if (how == BeamInput::Strain || how == BeamInput::Force) return in;
        if (how == BeamInput::ProfileScale) {
            // Its unit is a strain, a force or a length (the profile's
            // scales serve the displacement too): a beam takes no length.
            const auto scale = settings.scales.find(channels[c].name);
            const auto unit = physicalUnit(scale->second.unit);
            if (unit->kind != ChannelKind::Strain && unit->kind != ChannelKind::Force)
                throw std::invalid_argument("the beam " + channels[c].name + " is given a scale in " +
                                            scale->second.unit +
                                            ", a length; a beam's counts are read as a force (N, mN) or a strain "
                                            "(strain, µε)");
            in.kind = unit->kind;
            in.profileScaled = true;
            in.name = channels[c].name;
            in.unitsPerCount = unit->factor / scale->second.countsPerUnit;
            in.offset = scale->second.offset_counts;
            in.fullScale = scale->second.fullScale_counts;
            return in;
        }
        straingauge::BridgeSettings bridge = settings.bridge;
        bridge.gaugeFactor = gaugeFactor.value_or(bridge.gaugeFactor);
        in.chain.emplace(settings.adc, bridge);
        in.fullScale = in.chain->fullScaleCounts();
        return in;
    };
    m_high = input(beams[0], settings.highGaugeFactor);
    m_low = input(beams[1], settings.lowGaugeFactor);
}

bool PalpationForces::atLimit(bool highBeam, double raw) const
{
    const Input& beam = highBeam ? m_high : m_low;
    return beam.fullScale && std::abs(raw - beam.offset) >= (1.0 - kNearLimit) * *beam.fullScale;
}

std::optional<double> PalpationForces::gaugeFactor(bool highBeam) const
{
    const Input& beam = highBeam ? m_high : m_low;
    if (beam.chain) return beam.chain->bridge().gaugeFactor;
    return std::nullopt;
}

std::optional<BeamResolution> PalpationForces::resolution(bool highBeam) const
{
    const Input& beam = highBeam ? m_high : m_low;
    if (!beam.fullScale) return std::nullopt;
    return BeamResolution{forceOfChange(highBeam, 1.0), forceOfChange(highBeam, *beam.fullScale)};
}

void PalpationForces::setZero(const RawZero& zero)
{
    m_high.setZero(zero.high);
    m_low.setZero(zero.low);
    m_zero = zero;
}

std::optional<std::string> PalpationForces::unjudgedClipping() const
{
    std::string beams;
    for (const Input* beam : {&m_high, &m_low})
        if (beam->profileScaled && !beam->fullScale) beams += (beams.empty() ? "" : " and ") + beam->name;
    if (beams.empty()) return std::nullopt;
    return "the profile gives " + beams +
           " no \"full_scale\": where the converter clips is not known, so a press at its limit is read as any "
           "other (give the largest count from the offset its converter gives, as in the user guide's \"Raw ADC "
           "counts\")";
}

double PalpationForces::forceOfChange(bool highBeam, double rawChange) const
{
    const Input& beam = highBeam ? m_high : m_low;
    const auto& cantilever = highBeam ? m_pair.high() : m_pair.low();
    // About the count of zero (the quarter bridge's curvature is tiny there).
    const double at = m_zero ? (highBeam ? m_zero->high : m_zero->low) : beam.offset;
    return std::abs(beam.force(cantilever, at + rawChange) - beam.force(cantilever, at));
}

std::optional<ZeroUncertainty> PalpationForces::zeroUncertainty() const
{
    if (!m_zero || !m_zero->uncertainty) return std::nullopt;
    // The force of a raw value one uncertainty off the zero (the forces are
    // linear in the raw value but for the quarter bridge's tiny curvature).
    return ZeroUncertainty{std::abs(forceHigh(m_zero->high + m_zero->uncertainty->first)),
                           std::abs(forceLow(m_zero->low + m_zero->uncertainty->second))};
}

double PalpationForces::q(double forceHigh_n, double forceLow_n) const
{
    const bool contact = forceHigh_n > m_contactThreshold_n && forceLow_n > m_contactThreshold_n;
    return contact ? forceHigh_n / forceLow_n : kNaN;
}

double PalpationForces::stiffness(double q) const
{
    if (std::isnan(q)) return kNaN;
    const auto reading = m_pair.objectStiffness(q);
    return reading.range == sensors::ComplianceRange::InRange ? reading.objectStiffness_n_per_m : kNaN;
}

}  // namespace tactiscope::core::compliance
