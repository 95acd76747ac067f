// LiveSession: building each mode's unit (devices/session/LiveModeUnits)
// on the device's channels, the mode's profile and the store's newest
// calibrations, rebuilding it when they change, and the built-in units'
// parts the views read.
#include "devices/session/LiveSession.h"

#include "core/CompleteSamples.h"
#include "core/ModeCapability.h"
#include "core/SinkSlot.h"
#include "core/modes/ModeDefinition.h"
#include "core/sensors/BuiltInProfiles.h"
#include "devices/session/modes/CapacitiveUnit.h"
#include "devices/session/modes/PalpationUnit.h"
#include "devices/session/modes/PanelScanUnit.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::devices::session {

namespace {

// The channels a mode's processor reads: those playing its roles. A hole
// in one of them (NaN) is a gap to it; in another channel, nothing.
std::vector<std::size_t> channelsRead(core::Mode mode, const std::vector<core::ChannelDescriptor>& channels)
{
    const auto& definition = core::definitionOf(mode);
    std::vector<std::size_t> read;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        const auto role = channels[c].role;
        if (role && (std::ranges::find(definition.roles, *role) != definition.roles.end() ||
                     std::ranges::find(definition.optionalRoles, *role) != definition.optionalRoles.end()))
            read.push_back(c);
    }
    return read;
}

}  // namespace

const core::sensors::SensorProfile* LiveSession::profile(core::Mode mode) const
{
    const auto found = m_options.profiles.find(mode);
    return found == m_options.profiles.end() ? nullptr : &found->second;
}

const std::vector<core::storage::StoredCalibration>& LiveSession::calibrations(core::Mode mode) const
{
    static const std::vector<core::storage::StoredCalibration> none;
    const auto* unit = this->unit(mode);
    return unit ? unit->calibrations() : none;
}

std::optional<std::string> LiveSession::setProfile(core::Mode mode, core::sensors::SensorProfile profile)
{
    if (!core::sensors::profileFitsMode(profile, mode))
        return "'" + core::sensors::profileName(profile) + "' is not a probe for " + std::string(core::toString(mode)) +
               ": that mode takes " + std::string(core::sensors::profileKindFor(mode));
    if (isRecording() && mode == m_mode) return "a recording keeps its sensor from start to end; stop it first";
    const auto* current = this->profile(mode);
    if (core::sensors::profileRoles(profile) !=
            (current ? core::sensors::profileRoles(*current) : core::RoleAssignment{}) ||
        core::sensors::profileScales(profile) !=
            (current ? core::sensors::profileScales(*current) : core::sensors::ChannelScales{})) {
        // Other roles or scales: the channels and every processor are built again.
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

// Builds `mode`'s unit (none for a mode without one); returns the problem
// when it cannot (a bad profile: the unit it would replace, if any, runs
// on) or reads through less than asked (a calibration it refused).
// `inheritZero`: the new unit goes on from the old one's zero (the same
// channels, another profile or calibration).
std::optional<std::string> LiveSession::build(core::Mode mode, bool inheritZero)
{
    if (core::definitionOf(mode).profile != core::ProfileType::None && !profile(mode)) {
        auto builtIn = core::sensors::builtInProfile(mode);
        m_options.profiles.emplace(mode, std::move(*builtIn));
    }
    std::string refused;
    const LiveUnitSetup setup{m_channels,
                              source().nominalSampleRate_hz(),
                              m_options.displaySeconds,
                              m_options.storePath,
                              profile(mode),
                              m_options.panelSpacing_m,
                              inheritZero ? unitOf(mode) : nullptr,
                              &m_problems,
                              &refused};
    std::unique_ptr<LiveModeUnit> built;
    try {
        built = makeLiveUnit(mode, setup);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    const auto slot = m_slots.find(mode);
    if (slot == m_slots.end())  // registered after this session began: it has no place in the stream
        return "the " + std::string(core::toString(mode)) + " mode was added after this device connected";
    slot->second->set(built ? std::make_shared<core::CompleteSamples>(built->sink(), channelsRead(mode, m_channels))
                            : nullptr);
    if (built)
        m_units[mode] = std::move(built);
    else
        m_units.erase(mode);
    if (mode == m_mode) refreshReaders();  // a trigger or limit on its quantities reads the new processor
    if (!refused.empty()) return refused;
    return std::nullopt;
}

LiveModeUnit* LiveSession::unitOf(core::Mode mode) const
{
    const auto found = m_units.find(mode);
    return found == m_units.end() ? nullptr : found->second.get();
}

const LiveModeUnit* LiveSession::unit(core::Mode mode) const
{
    return unitOf(mode);
}

}  // namespace tactiscope::devices::session
