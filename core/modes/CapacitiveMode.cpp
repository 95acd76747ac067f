// The capacitive mode (seed 002): one capacitance channel read through a
// capacitive beam's profile and its C0 and sensitivity calibration. In
// review, the capacitance as stored, then ΔC, the force and the deflection
// (core/derived/CapacitiveChannels), read through another calibration when
// the options say so (a re-analysis).
#include "core/derived/CapacitiveChannels.h"
#include "core/derived/DerivedLane.h"
#include "core/derived/ModeLanes.h"
#include "core/derived/SessionLanes.h"
#include "core/modes/ModeDefinition.h"

#include <array>

namespace tactiscope::core {
namespace {

constexpr std::array kRoles{ChannelRole::Capacitance};
constexpr std::array kOptionalRoles{ChannelRole::ReferenceForce};

derived::ModeLanes lanes(storage::SessionSource& store, const storage::SessionSummary& session,
                         const derived::LaneOptions& options)
{
    auto capacitive = std::make_shared<derived::CapacitiveChannels>(store, session.id, options.capacitiveCalibration);
    const std::size_t c = capacitive->capacitanceChannel();
    derived::ModeLanes result;
    result.before.push_back(
        std::make_unique<storage::StoredLane>(store, session.id, c, store.channels(session.id)[c].descriptor));
    for (const std::size_t d : {std::size_t{0}, std::size_t{2}, std::size_t{3}})
        result.before.push_back(std::make_unique<derived::DerivedLane<derived::CapacitiveChannels>>(capacitive, d));
    result.replaced = {c};
    result.basis = capacitive->basis();
    return result;
}

std::unique_ptr<storage::ComputedColumns> columns(storage::SessionSource& store, std::int64_t session)
{
    return std::make_unique<derived::CapacitiveChannels>(store, session);
}

}  // namespace

const ModeDefinition& capacitiveMode()
{
    static const ModeDefinition definition{
        .mode = Mode::Capacitive,
        .name = "capacitive",
        .title = "Capacitive",
        .needs = "a capacitance",
        .roles = kRoles,
        .optionalRoles = kOptionalRoles,
        .profile = ProfileType::CapacitiveBeam,
        .detectsDefects = false,
        .readings = std::nullopt,
        .noZero = {},
        .lanes = lanes,
        .computedColumns = columns,
    };
    return definition;
}

}  // namespace tactiscope::core
