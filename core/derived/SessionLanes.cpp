// SessionLanes: the mode's lanes (its definition's) around the stored ones.
#include "core/derived/SessionLanes.h"

#include "core/modes/ModeDefinition.h"
#include "core/timing/ClockMappingJson.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core::derived {

namespace {

// A session of several devices: each device's stored channels, named
// DEVICE/CHANNEL, at its rate and placed by its clock on the session's.
// Each device's analysis is its own part's; its quantities are not
// derived across devices here.
SessionLanes partLanes(storage::SessionSource& store, const std::vector<storage::SessionPart>& parts)
{
    SessionLanes result;
    for (const auto& part : parts) {
        const auto channels = store.channels(part.id);
        if (channels.empty()) continue;
        storage::LaneClock clock{channels.front().sampleRate_hz, store.sampleCount(part.id),
                                 timing::clockMappingFromJson(part.clockJson)};
        for (std::size_t c = 0; c < channels.size(); ++c) {
            auto descriptor = channels[c].descriptor;
            descriptor.name = part.deviceName + "/" + descriptor.name;
            result.lanes.push_back(std::make_unique<storage::StoredLane>(store, part.id, c, descriptor, clock));
        }
        if (!clock.mapping)
            result.problem += (result.problem.empty() ? "" : "; ") + part.deviceName +
                              ": its clock was not mapped, its samples are placed by its own times";
    }
    return result;
}

}  // namespace

SessionLanes sessionLanes(storage::SessionSource& store, const storage::SessionSummary& session,
                          const LaneOptions& options)
{
    SessionLanes result;
    if (const auto parts = store.parts(session.id); !parts.empty()) return partLanes(store, parts);
    const auto channels = store.channels(session.id);
    ModeLanes added;
    const auto& definition = definitionOf(session.metadata.mode);
    if (!options.raw && definition.lanes) {
        try {
            added = definition.lanes(store, session, options);
            result.basis = added.basis;
            result.derived = true;
        } catch (const std::invalid_argument& e) {
            added = {};
            result.problem = e.what();
        }
    }
    for (auto& lane : added.before) result.lanes.push_back(std::move(lane));
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (std::ranges::find(added.replaced, c) == added.replaced.end())
            result.lanes.push_back(std::make_unique<storage::StoredLane>(store, session.id, c, channels[c].descriptor));
    for (auto& lane : added.after) result.lanes.push_back(std::move(lane));
    return result;
}

std::unique_ptr<storage::ComputedColumns> computedColumns(storage::SessionSource& store,
                                                          const storage::SessionSummary& session)
{
    if (const auto refusal = storage::oneDeviceRefusal(store, session.id, "the mode's physical quantities"))
        throw std::invalid_argument(*refusal);
    const auto& definition = definitionOf(session.metadata.mode);
    if (!definition.computedColumns)
        throw std::invalid_argument("session " + std::to_string(session.id) + " is a " + std::string(definition.name) +
                                    " recording: its channels are stored as they came, with no derived quantities");
    return definition.computedColumns(store, session.id);
}

}  // namespace tactiscope::core::derived
