// The panel-scan mode's live part: the surface-deflection detector on
// cantilevers A and B, the panel's defects on the lists' clock, stored as
// defect events while a panel scan records, and the automatic verdict on
// the panel's sites at its end, placed by the rig's position channel when
// it has one. A probe that sends its own decisions has them recorded as
// the analysis "probe", a lasting disagreement as an alarm, and their
// agreement in the verdict's grounds.
#pragma once

#include "core/detector/DefectSites.h"
#include "core/detector/LiveDetection.h"
#include "devices/session/LiveModeUnit.h"

namespace tactiscope::devices::session {

class PanelScanUnit final : public LiveModeUnit {
public:
    // Throws std::invalid_argument when the detector cannot run on the stream.
    explicit PanelScanUnit(const LiveUnitSetup& setup);

    std::shared_ptr<core::BlockSink> sink() const override { return m_detection; }
    // The detector's output: its decision (-1, 0, +1) and both partial correlations.
    std::vector<LiveQuantity> quantities() const override
    {
        return {{"decision", "", core::ChannelKind::Decision, m_detection->output(), 0},
                {"r_ab", "", core::ChannelKind::Other, m_detection->output(), 1},
                {"r_ba", "", core::ChannelKind::Other, m_detection->output(), 2}};
    }
    std::optional<std::string> tare() override;
    void startRecording(core::storage::Recorder& recorder) override;
    void take(const LiveTake& take) override;
    void clearLists() override { m_defects.clear(); }
    std::optional<core::storage::VerdictDecision> finishRecording(RecordingSummary& summary, bool whole) override;
    std::string storedText(const RecordingSummary& summary) const override;

    const std::shared_ptr<core::detector::LiveDetection>& detection() const { return m_detection; }
    const std::vector<core::detector::DefectEvent>& defects() const { return m_defects; }
    // Placed by the rig's position channel when the stream has one, as the
    // stored session's are (core/storage/StoredSites.h).
    core::detector::SiteGrouping sites() const
    {
        return core::detector::scanSites(m_defects, m_detection->placesByPosition());
    }
    // Why the last recording got no verdict ("too short to judge (…)");
    // empty when it got one, and while recording.
    const std::string& notJudged() const { return m_notJudged; }

private:
    void takeProbeDecisions(const LiveTake& take);
    std::optional<core::detector::ProbeAgreement> agreementSinceStart() const;

    std::shared_ptr<core::detector::LiveDetection> m_detection;
    std::vector<core::detector::DefectEvent> m_defects;
    std::vector<core::detector::DefectEvent> m_later;  // stream times, after the samples recorded
    // The probe's own decisions, when it sends them: into the recording only.
    std::vector<core::detector::DefectEvent> m_laterProbe;
    std::vector<core::storage::SessionEvent> m_laterAlarms;
    std::optional<core::detector::ProbeAgreement> m_agreementAtStart;
    std::string m_notJudged;
};

}  // namespace tactiscope::devices::session
