// The panel-scan mode (seed 000): two strain cantilevers, the surface-
// deflection detector's defects and automatic verdict; in review, the
// strains as stored, then the detector's best R against its threshold and
// its decision (core/derived/PanelScanChannels).
#include "core/derived/DerivedLane.h"
#include "core/derived/ModeLanes.h"
#include "core/derived/PanelScanChannels.h"
#include "core/modes/ModeDefinition.h"

#include <array>

namespace tactiscope::core {
namespace {

constexpr std::array kRoles{ChannelRole::CantileverA, ChannelRole::CantileverB};
// Where the probe is along the stroke, when the rig knows: each crossing's
// place then comes from it (core/detector/DefectSites.h).
constexpr std::array kOptionalRoles{ChannelRole::Position};

derived::ModeLanes lanes(storage::SessionSource& store, const storage::SessionSummary& session,
                         const derived::LaneOptions&)
{
    auto detector = std::make_shared<derived::PanelScanChannels>(store, session.id);
    derived::ModeLanes result;
    result.after.push_back(std::make_unique<derived::DerivedLane<derived::PanelScanChannels>>(
        detector, 0, detector->parameters().threshold));
    result.after.push_back(std::make_unique<derived::DerivedLane<derived::PanelScanChannels>>(detector, 1));
    result.basis = detector->basis();
    return result;
}

std::unique_ptr<storage::ComputedColumns> columns(storage::SessionSource& store, std::int64_t session)
{
    return std::make_unique<derived::PanelScanChannels>(store, session);
}

}  // namespace

const ModeDefinition& panelScanMode()
{
    static const ModeDefinition definition{
        .mode = Mode::PanelScan,
        .name = "panel-scan",
        .title = "Panel scan",
        .needs = "two strain cantilevers (A and B)",
        .roles = kRoles,
        .optionalRoles = kOptionalRoles,
        .profile = ProfileType::None,
        .detectsDefects = true,
        .shortestJudged = "the detector's longest lag plus three of its forgetting times "
                          "(core/detector/DetectorParameters.h: shortestJudged_s; 0.6 s at the paper's settings)",
        .readings = std::nullopt,
        .noZero = "panel scan has no zero to take: the detector works on the signals' changes",
        .lanes = lanes,
        .computedColumns = columns,
    };
    return definition;
}

}  // namespace tactiscope::core
