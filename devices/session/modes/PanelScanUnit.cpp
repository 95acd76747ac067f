// PanelScanUnit: the detector, the panel's defects and its verdict.
#include "devices/session/modes/PanelScanUnit.h"

#include "core/ModeCapability.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/Recorder.h"
#include "core/text/CountText.h"

#include <stdexcept>

namespace tactiscope::devices::session {
namespace {

std::shared_ptr<core::detector::LiveDetection> detectorFor(const LiveUnitSetup& setup)
{
    core::detector::LiveDetectionSettings settings;
    try {
        settings.parameters.lags_s = core::detector::liveLags_s(setup.rate_hz);
        settings.spacing_m = setup.panelSpacing_m;
        return std::make_shared<core::detector::LiveDetection>(
            *core::modeChannels(core::Mode::PanelScan, setup.channels), setup.rate_hz, settings, setup.displaySeconds);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("the surface-deflection detector cannot run on this stream: ") +
                                    e.what());
    }
}

}  // namespace

PanelScanUnit::PanelScanUnit(const LiveUnitSetup& setup)
    : m_detection(detectorFor(setup))
{
}

std::optional<std::string> PanelScanUnit::tare()
{
    return std::string(core::panelScanMode().noZero);
}

void PanelScanUnit::take(const LiveTake& take)
{
    const auto found = resultsForLists(m_later, m_detection->takeEvents(), take);
    if (found.empty()) return;
    m_defects.insert(m_defects.end(), found.begin(), found.end());
    if (!take.recorder) return;
    std::vector<core::storage::SessionEvent> stored;
    stored.reserve(found.size());
    for (const auto& e : found) stored.push_back(core::storage::defectRecord(e));
    take.recorder->addEvents(std::move(stored));
}

// A panel the probe left before the stop was not wholly inspected: no
// automatic verdict says it passed.
std::optional<core::storage::VerdictDecision> PanelScanUnit::finishRecording(RecordingSummary& summary, bool whole)
{
    summary.defects = m_defects.size();
    summary.sites = sites().sites.size();
    if (!whole) return std::nullopt;
    auto decision = core::storage::automaticDecision(core::storage::kLiveAnalysis, m_defects.size(), summary.sites,
                                                     m_detection->settings().parameters);
    summary.verdict = decision.verdict;
    return decision;
}

std::string PanelScanUnit::storedText(const RecordingSummary& summary) const
{
    using core::text::countText;
    return countText(summary.defects, "defect", "defects") + " stored" +
           (summary.defects == 0 ? std::string() : " at " + countText(summary.sites, "site", "sites")) + ", verdict " +
           (summary.verdict ? std::string(core::verdictText(summary.verdict)) : std::string("none"));
}

}  // namespace tactiscope::devices::session
