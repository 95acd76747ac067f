// SessionLanes: the mode's lanes (its definition's) around the stored ones.
#include "core/derived/SessionLanes.h"

#include "core/modes/ModeDefinition.h"
#include "core/signal/SignalColumns.h"
#include "core/timing/ClockMappingJson.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace tactiscope::core::derived {

namespace {

// A lane a part's mode derived, on its device's clock and named after it.
class PartLane final : public storage::LaneSource {
public:
    PartLane(std::unique_ptr<storage::LaneSource> lane, const std::string& device, storage::LaneClock clock)
        : m_lane(std::move(lane)),
          m_descriptor(m_lane->descriptor()),
          m_clock(std::move(clock))
    {
        m_descriptor.name = device + "/" + m_descriptor.name;
    }
    ChannelDescriptor descriptor() const override { return m_descriptor; }
    std::optional<storage::LaneClock> clock() const override { return m_clock; }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override { return m_lane->exact(first, count); }
    std::vector<storage::OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) override
    {
        return m_lane->overview(first, count, points);
    }
    std::optional<double> threshold() const override { return m_lane->threshold(); }

private:
    std::unique_ptr<storage::LaneSource> m_lane;
    ChannelDescriptor m_descriptor;
    storage::LaneClock m_clock;
};

// The lanes of one recording: its mode's quantities around its stored
// channels (replaced ones left out), each made into a lane by `lane`.
void addRecordingLanes(
    SessionLanes& result, storage::SessionSource& store, const storage::SessionSummary& session,
    const LaneOptions& options, const std::string& device,
    const std::function<std::unique_ptr<storage::LaneSource>(std::unique_ptr<storage::LaneSource>)>& placed,
    const std::function<std::unique_ptr<storage::LaneSource>(std::size_t, ChannelDescriptor)>& stored)
{
    const auto channels = store.channels(session.id);
    ModeLanes added;
    const auto& definition = definitionOf(session.metadata.mode);
    if (!options.raw && definition.lanes) {
        try {
            added = definition.lanes(store, session, options);
            result.basis += (result.basis.empty() ? "" : "; ") + (device.empty() ? "" : device + ": ") + added.basis;
            result.derived = true;
        } catch (const std::invalid_argument& e) {
            added = {};
            result.problem += (result.problem.empty() ? "" : "; ") + (device.empty() ? "" : device + ": ") + e.what();
        }
    }
    const auto push = [&](std::unique_ptr<storage::LaneSource> lane) {
        result.lanes.push_back(std::move(lane));
        result.modes.push_back(session.metadata.mode);
        result.devices.push_back(device);
    };
    for (auto& lane : added.before) push(placed(std::move(lane)));
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (std::ranges::find(added.replaced, c) == added.replaced.end()) push(stored(c, channels[c].descriptor));
    for (auto& lane : added.after) push(placed(std::move(lane)));
    const auto tell = [&](const std::string& problem) {
        result.problem += (result.problem.empty() ? "" : "; ") + (device.empty() ? "" : device + ": ") + problem;
    };
    // The filtered and math channels it was recorded with, as the operator saw them.
    if (!options.raw) {
        std::string problem;
        for (auto& lane : signal::recordedSignalLanes(store, session.id, problem)) push(placed(std::move(lane)));
        if (!problem.empty()) tell(problem);
    }
    // The reviewer's filters on its channels, each lane named as the review names it.
    const auto laneNames = signal::reviewFilterLaneNames(options.reviewFilters);
    for (std::size_t k = 0; k < options.reviewFilters.size(); ++k) {
        const auto& filter = options.reviewFilters[k];
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const std::string& name = channels[c].descriptor.name;
            if ((device.empty() ? name : device + "/" + name) != filter.channel) continue;
            try {
                // placed() adds the DEVICE/ the full name already has.
                push(placed(std::make_unique<signal::ReviewFilterLane>(
                    store, session.id, c, channels[c].descriptor, channels[c].sampleRate_hz, filter.settings,
                    laneNames[k].substr(device.empty() ? 0 : device.size() + 1))));
            } catch (const std::invalid_argument& e) {
                tell(name + " cannot be filtered so: " + e.what());
            }
        }
    }
}

// A session of several devices: each device's lanes as its own recording
// has them (its mode's quantities and its stored channels), named
// DEVICE/NAME, at its rate and placed by its clock on the session's.
SessionLanes partLanes(storage::SessionSource& store, const std::vector<storage::SessionPart>& parts,
                       const LaneOptions& options)
{
    SessionLanes result;
    for (const auto& part : parts) {
        const auto channels = store.channels(part.id);
        const auto recording = store.session(part.id);
        if (channels.empty() || !recording) continue;
        const storage::LaneClock clock{channels.front().sampleRate_hz, store.sampleCount(part.id),
                                       timing::clockMappingFromJson(part.clockJson)};
        addRecordingLanes(
            result, store, *recording, options, part.deviceName,
            [&](std::unique_ptr<storage::LaneSource> lane) {
                return std::make_unique<PartLane>(std::move(lane), part.deviceName, clock);
            },
            [&](std::size_t c, ChannelDescriptor descriptor) {
                descriptor.name = part.deviceName + "/" + descriptor.name;
                return std::make_unique<storage::StoredLane>(store, part.id, c, std::move(descriptor), clock);
            });
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
    if (const auto parts = store.parts(session.id); !parts.empty()) return partLanes(store, parts, options);
    SessionLanes result;
    addRecordingLanes(
        result, store, session, options, {}, [](std::unique_ptr<storage::LaneSource> lane) { return lane; },
        [&](std::size_t c, ChannelDescriptor descriptor) -> std::unique_ptr<storage::LaneSource> {
            return std::make_unique<storage::StoredLane>(store, session.id, c, std::move(descriptor));
        });
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
