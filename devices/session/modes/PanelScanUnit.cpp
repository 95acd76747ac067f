// PanelScanUnit: the detector, the panel's defects and its verdict.
#include "devices/session/modes/PanelScanUnit.h"

#include "core/ModeCapability.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/Recorder.h"
#include "core/text/CountText.h"

#include <cstdio>
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
            *core::modeChannels(core::Mode::PanelScan, setup.channels), setup.rate_hz, settings, setup.displaySeconds,
            core::detector::probeDecisionChannels(setup.channels), core::detector::positionChannel(setup.channels));
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

void PanelScanUnit::startRecording(core::storage::Recorder& recorder)
{
    LiveModeUnit::startRecording(recorder);
    m_agreementAtStart = m_detection->probeAgreement();
    m_notJudged.clear();
}

void PanelScanUnit::take(const LiveTake& take)
{
    takeProbeDecisions(take);
    const auto found = resultsForLists(m_later, m_detection->takeEvents(), take);
    if (found.empty()) return;
    m_defects.insert(m_defects.end(), found.begin(), found.end());
    if (!take.recorder) return;
    std::vector<core::storage::SessionEvent> stored;
    stored.reserve(found.size());
    for (const auto& e : found) stored.push_back(core::storage::defectRecord(e));
    take.recorder->addEvents(std::move(stored));
}

// The probe's events and alarms go into the recording (the lists show the
// workstation's), on its clock, held back like the defects past its end.
void PanelScanUnit::takeProbeDecisions(const LiveTake& take)
{
    std::vector<core::storage::SessionEvent> alarms;
    for (const auto& d : m_detection->takeDisagreements()) {
        if (take.tell) take.tell(d.start_s, d.text());  // the operator hears it at once
        alarms.push_back(core::storage::alarmRecord(d.start_s, d.start_s, d.text()));
    }
    LiveTake recordOnly = take;
    recordOnly.adding = [] {};
    const auto probe = resultsForLists(m_laterProbe, m_detection->takeProbeEvents(), recordOnly);
    auto told = resultsForLists(m_laterAlarms, std::move(alarms), recordOnly);
    if (!take.recorder) return;
    auto stored = core::storage::defectRecords(probe, core::storage::kProbeAnalysis);
    // A probe that sends no lags: its events have none, and so no speed (not a lag of 0 ms).
    for (auto& e : stored) {
        if (e.lag_s && *e.lag_s > 0.0) continue;
        e.lag_s.reset();
        e.speed_m_per_s.reset();
    }
    stored.insert(stored.end(), std::make_move_iterator(told.begin()), std::make_move_iterator(told.end()));
    if (!stored.empty()) take.recorder->addEvents(std::move(stored));
}

// A panel the probe left before the stop was not wholly inspected: no
// automatic verdict says it passed.
std::optional<core::storage::VerdictDecision> PanelScanUnit::finishRecording(RecordingSummary& summary, bool whole)
{
    summary.defects = m_defects.size();
    const auto grouping = sites();
    summary.sites = grouping.sites.size();
    for (std::size_t i = 0; i < grouping.sites.size(); ++i) {
        const auto& site = grouping.sites[i];
        char times[64];
        std::snprintf(times, sizeof times, "%.1f–%.1f s", site.first_s, site.last_s);
        summary.findings.push_back("Site " + std::to_string(i + 1) + ": " + core::detector::siteText(site) + ", " +
                                   std::to_string(site.forward) + " A then B, " + std::to_string(site.backward) +
                                   " B then A, " + times);
    }
    summary.probeAgreement = agreementSinceStart();
    if (!whole) return std::nullopt;
    // The rule the panel-scan definition states (shortestJudged): a panel
    // recorded for less than the detector needs was not inspected.
    const auto& parameters = m_detection->settings().parameters;
    const double recorded_s = summary.end_s + parameters.sampleInterval_s;
    if (const double needed_s = core::detector::shortestJudged_s(parameters); recorded_s < needed_s) {
        char text[96];
        std::snprintf(text, sizeof text, "too short to judge (%.3g s of the %.3g s the detector needs)", recorded_s,
                      needed_s);
        summary.notJudged = m_notJudged = text;
        return std::nullopt;
    }
    auto decision = core::storage::automaticDecision(core::storage::kLiveAnalysis, m_defects.size(), summary.sites,
                                                     m_detection->settings().parameters, summary.probeAgreement);
    summary.verdict = decision.verdict;
    return decision;
}

std::optional<core::detector::ProbeAgreement> PanelScanUnit::agreementSinceStart() const
{
    auto now = m_detection->probeAgreement();
    if (!now || !m_agreementAtStart) return now;
    now->compared -= m_agreementAtStart->compared;
    now->agreeing -= m_agreementAtStart->agreeing;
    return now;
}

std::string PanelScanUnit::storedText(const RecordingSummary& summary) const
{
    using core::text::countText;
    std::string text =
        countText(summary.defects, "defect", "defects") + " stored" +
        (summary.defects == 0 ? std::string() : " at " + countText(summary.sites, "site", "sites")) +
        (summary.notJudged.empty()
             ? ", verdict " + (summary.verdict ? std::string(core::verdictText(summary.verdict)) : std::string("none"))
             : ", " + summary.notJudged);
    if (summary.probeAgreement) text += "; " + core::detector::agreementText(*summary.probeAgreement);
    return text;
}

}  // namespace tactiscope::devices::session
