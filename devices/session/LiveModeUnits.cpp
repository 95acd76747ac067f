// LiveModeUnits: the one list of the modes' live units, and the defaults
// of the unit interface.
#include "devices/session/LiveModeUnit.h"

#include "devices/session/modes/CapacitiveUnit.h"
#include "devices/session/modes/PalpationUnit.h"
#include "devices/session/modes/PanelScanUnit.h"

#include <map>

namespace tactiscope::devices::session {
namespace {

std::map<core::Mode, LiveUnitFactory>& factories()
{
    static std::map<core::Mode, LiveUnitFactory> units{
        {core::Mode::PanelScan, [](const LiveUnitSetup& setup) { return std::make_unique<PanelScanUnit>(setup); }},
        {core::Mode::Palpation, [](const LiveUnitSetup& setup) { return std::make_unique<PalpationUnit>(setup); }},
        {core::Mode::Capacitive, [](const LiveUnitSetup& setup) { return std::make_unique<CapacitiveUnit>(setup); }},
    };
    return units;
}

}  // namespace

std::unique_ptr<LiveModeUnit> makeLiveUnit(core::Mode mode, const LiveUnitSetup& setup)
{
    const auto found = factories().find(mode);
    if (found == factories().end()) return nullptr;
    return found->second(setup);
}

void registerLiveUnit(core::Mode mode, LiveUnitFactory factory)
{
    factories()[mode] = std::move(factory);
}

void unregisterLiveUnit(core::Mode mode)
{
    factories().erase(mode);
}

const std::vector<core::storage::StoredCalibration>& LiveModeUnit::calibrations() const
{
    static const std::vector<core::storage::StoredCalibration> none;
    return none;
}

void LiveModeUnit::startRecording(core::storage::Recorder&) {}

void LiveModeUnit::takeZeros(const LiveTake&) {}

std::optional<core::storage::VerdictDecision> LiveModeUnit::finishRecording(RecordingSummary&, bool)
{
    return std::nullopt;
}

}  // namespace tactiscope::devices::session
