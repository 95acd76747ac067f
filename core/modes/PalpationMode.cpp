// The palpation mode (seed 001): a stiff and a soft beam and a
// displacement, read through a compliance pair's profile; its presses are
// stored as stiffness readings. In review, F_H, F_L, Q and k_o first
// (core/derived/PalpationChannels), then the stored channels the forces
// did not come from.
#include "core/derived/DerivedLane.h"
#include "core/derived/ModeLanes.h"
#include "core/derived/PalpationChannels.h"
#include "core/modes/ModeDefinition.h"

#include <array>

namespace tactiscope::core {
namespace {

constexpr std::array kRoles{ChannelRole::StiffBeam, ChannelRole::SoftBeam, ChannelRole::Displacement};

derived::ModeLanes lanes(storage::SessionSource& store, const storage::SessionSummary& session,
                         const derived::LaneOptions&)
{
    auto palpation = std::make_shared<derived::PalpationChannels>(store, session.id);
    derived::ModeLanes result;
    for (std::size_t d = 0; d < palpation->channels().size(); ++d)
        result.before.push_back(std::make_unique<derived::DerivedLane<derived::PalpationChannels>>(palpation, d));
    result.replaced = {palpation->highChannel(), palpation->lowChannel()};
    result.basis = palpation->basis();
    return result;
}

std::unique_ptr<storage::ComputedColumns> columns(storage::SessionSource& store, std::int64_t session)
{
    return std::make_unique<derived::PalpationChannels>(store, session);
}

}  // namespace

const ModeDefinition& palpationMode()
{
    static const ModeDefinition definition{
        .mode = Mode::Palpation,
        .name = "palpation",
        .title = "Palpation",
        .needs = "a stiff and a soft beam and a displacement",
        .roles = kRoles,
        .profile = ProfileType::CompliancePair,
        .detectsDefects = false,
        .readings = ReadingKind::Compliance,
        .noZero = {},
        .lanes = lanes,
        .computedColumns = columns,
    };
    return definition;
}

}  // namespace tactiscope::core
