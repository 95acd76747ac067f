// LiveSession: building each mode's processor from the device's channels,
// the mode's profile and the newest calibrations in the store, and
// rebuilding it when the profile or the calibrations change.
#include "devices/session/LiveSession.h"

#include "core/ModeCapability.h"
#include "core/SinkSlot.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/capacitive/LiveCapacitive.h"
#include "core/compliance/LivePalpation.h"
#include "core/detector/LiveDetection.h"
#include "core/modes/ModeDefinition.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/SessionStore.h"

#include <stdexcept>

namespace tactiscope::devices::session {

const core::sensors::SensorProfile* LiveSession::profile(core::Mode mode) const
{
    const auto found = m_options.profiles.find(mode);
    return found == m_options.profiles.end() ? nullptr : &found->second;
}

const std::vector<core::storage::StoredCalibration>& LiveSession::calibrations(core::Mode mode) const
{
    static const std::vector<core::storage::StoredCalibration> none;
    const auto found = m_calibrations.find(mode);
    return found == m_calibrations.end() ? none : found->second;
}

std::optional<std::string> LiveSession::setProfile(core::Mode mode, core::sensors::SensorProfile profile)
{
    if (!core::sensors::profileFitsMode(profile, mode))
        return "'" + core::sensors::profileName(profile) + "' is not a probe for " + std::string(core::toString(mode)) +
               ": that mode takes " + std::string(core::sensors::profileKindFor(mode));
    if (isRecording() && mode == m_mode) return "a recording keeps its sensor from start to end; stop it first";
    const auto* current = this->profile(mode);
    if (core::sensors::profileRoles(profile) !=
        (current ? core::sensors::profileRoles(*current) : core::RoleAssignment{})) {
        // Other roles: the channels and every processor are built again.
        if (isRecording()) return "a recording keeps its channels' roles; stop it first";
        auto previous = std::exchange(m_options.profiles[mode], std::move(profile));
        if (auto problem = rebuildChannels()) {
            m_options.profiles[mode] = std::move(previous);
            rebuildChannels();
            return problem;
        }
        return std::nullopt;
    }
    auto previous = std::exchange(m_options.profiles[mode], std::move(profile));
    if (refusalOf(mode)) return std::nullopt;  // kept for a device that can feed the mode
    if (auto problem = build(mode)) {
        m_options.profiles[mode] = std::move(previous);
        build(mode);
        return problem;
    }
    return std::nullopt;
}

std::optional<std::string> LiveSession::reloadCalibrations(core::Mode mode)
{
    if (isRecording() && mode == m_mode) return "a recording keeps its calibration from start to end";
    if (refusalOf(mode)) return std::nullopt;
    return build(mode);
}

std::optional<std::string> LiveSession::setStorePath(const std::string& path)
{
    if (isRecording()) return "a recording keeps its session store to its end";
    m_options.storePath = path;
    for (const auto& definition : core::modeDefinitions())
        if (definition.profile != core::ProfileType::None && !refusalOf(definition.mode))
            if (auto problem = build(definition.mode)) m_problems.push_back(std::move(*problem));
    return std::nullopt;
}

// Builds `mode`'s processor; returns the problem when it cannot (a bad
// profile, a bad calibration), in which case the mode runs without one.
// `inheritZero`: the new processor goes on from the old one's zero (the
// same channels, another profile or calibration).
std::optional<std::string> LiveSession::build(core::Mode mode, bool inheritZero)
{
    if (core::definitionOf(mode).profile != core::ProfileType::None && !profile(mode)) {
        auto builtIn = core::sensors::builtInProfile(mode);
        m_options.profiles.emplace(mode, std::move(*builtIn));
    }
    switch (mode) {
    case core::Mode::PanelScan:
        buildDetection();
        return std::nullopt;
    case core::Mode::Palpation:
        return buildPalpation(inheritZero);
    case core::Mode::Capacitive:
        return buildCapacitive(inheritZero);
    case core::Mode::General:
        return std::nullopt;  // the channels are recorded as they come
    }
    return std::nullopt;
}

void LiveSession::buildDetection()
{
    const auto& channels = m_channels;
    const double rate_hz = source().nominalSampleRate_hz();
    core::detector::LiveDetectionSettings settings;
    try {
        settings.parameters.lags_s = core::detector::liveLags_s(rate_hz);
        settings.spacing_m = m_options.panelSpacing_m;
        m_detection = std::make_shared<core::detector::LiveDetection>(
            *core::modeChannels(core::Mode::PanelScan, channels), rate_hz, settings, m_options.displaySeconds);
        m_detectionSlot->set(m_detection);
    } catch (const std::invalid_argument& e) {
        m_problems.push_back(std::string("the surface-deflection detector cannot run on this stream: ") + e.what());
    }
}

// A store that exists but cannot be read is a problem to tell: the
// processor then reads through the nominal values, and says so.
std::optional<core::storage::StoredCalibration> LiveSession::newestCalibration(std::string_view kind,
                                                                               const std::string& sensor)
{
    try {
        return core::storage::newestCalibrationIn(m_options.storePath, kind, sensor);
    } catch (const core::storage::StorageError& e) {
        m_problems.push_back("the calibrations of '" + sensor + "' could not be read from " + m_options.storePath +
                             " (its nominal values are used): " + e.what());
        return std::nullopt;
    }
}

std::optional<std::string> LiveSession::buildPalpation(bool inheritZero)
{
    const auto& probe = std::get<core::sensors::CompliancePairProfile>(m_options.profiles.at(core::Mode::Palpation));
    const double rate_hz = source().nominalSampleRate_hz();
    // Each beam reads through its newest gauge-factor calibration, if any.
    std::vector<core::storage::StoredCalibration> newest;
    for (const bool stiff : {true, false}) {
        if (auto record = newestCalibration(core::calibration::kGaugeFactorKind,
                                            core::calibration::beamSensorName(probe.name, stiff)))
            newest.push_back(std::move(*record));
    }
    std::vector<core::calibration::CalibrationRecord> records;
    for (const auto& stored : newest) records.push_back(stored.record);
    std::vector<std::size_t> usable;
    const auto settings = core::compliance::palpationSettings(probe, rate_hz, records, &usable);
    auto& used = m_calibrations[core::Mode::Palpation];
    used.clear();
    for (const std::size_t i : usable) used.push_back(newest[i]);
    try {
        auto built =
            std::make_shared<core::compliance::LivePalpation>(m_channels, rate_hz, settings, m_options.displaySeconds);
        if (inheritZero && m_palpation) built->inheritZero(*m_palpation);
        m_palpation = std::move(built);
    } catch (const std::invalid_argument& e) {
        m_palpation.reset();
        used.clear();
        m_palpationSlot->set(nullptr);
        return "the profile '" + probe.name + "' cannot be used: " + e.what();
    }
    m_palpationSlot->set(m_palpation);
    return std::nullopt;
}

std::optional<std::string> LiveSession::buildCapacitive(bool inheritZero)
{
    const auto& probe = std::get<core::sensors::CapacitiveBeamProfile>(m_options.profiles.at(core::Mode::Capacitive));
    std::optional<std::string> problem;
    auto& used = m_calibrations[core::Mode::Capacitive];
    used.clear();
    try {
        std::vector<core::storage::StoredCalibration> newest;
        if (auto record = newestCalibration(core::calibration::kCapacitiveKind, probe.name))
            newest.push_back(std::move(*record));
        std::vector<core::calibration::CalibrationRecord> records;
        for (const auto& stored : newest) records.push_back(stored.record);
        std::optional<std::size_t> usable;
        std::string refused;
        const auto [sensitivity, drift] = core::capacitive::readoutSettings(probe, records, &usable, &refused);
        if (usable) used.push_back(newest[*usable]);
        if (!refused.empty()) problem = refused;
        auto built = std::make_shared<core::capacitive::LiveCapacitive>(m_channels, source().nominalSampleRate_hz(),
                                                                        sensitivity, drift, m_options.displaySeconds);
        if (inheritZero && m_capacitive) built->inheritBaseline(*m_capacitive);
        m_capacitive = std::move(built);
    } catch (const std::invalid_argument& e) {
        m_capacitive.reset();
        used.clear();
        m_capacitiveSlot->set(nullptr);
        return "the profile '" + probe.name + "' cannot be used: " + e.what();
    }
    m_capacitiveSlot->set(m_capacitive);
    return problem;
}

}  // namespace tactiscope::devices::session
