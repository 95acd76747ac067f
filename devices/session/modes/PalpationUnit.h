// The palpation mode's live part: the compliance probe's forces through
// its profile and each beam's newest gauge-factor calibration, the presses
// on the lists' clock with the site each was taken at (a phantom's grid
// cell, else the recording's site), stored as stiffness readings (in range
// only) while a palpation records, and the zeros the forces read on.
#pragma once

#include "core/compliance/LivePalpation.h"
#include "core/compliance/SiteGrid.h"
#include "devices/session/LiveModeUnit.h"

namespace tactiscope::devices::session {

class PalpationUnit final : public LiveModeUnit {
public:
    // Throws std::invalid_argument for a probe or channels it cannot use.
    explicit PalpationUnit(const LiveUnitSetup& setup);

    std::shared_ptr<core::BlockSink> sink() const override { return m_palpation; }
    const std::vector<core::storage::StoredCalibration>& calibrations() const override { return m_calibrations; }
    // By the names the review's derived lanes have (core/derived).
    std::vector<LiveQuantity> quantities() const override
    {
        return {{"force_high", "N", core::ChannelKind::Force, m_palpation->output(), 0},
                {"force_low", "N", core::ChannelKind::Force, m_palpation->output(), 1},
                {"Q", "", core::ChannelKind::Other, m_palpation->output(), 2}};
    }
    std::optional<std::string> tare() override { return m_palpation->tare(); }
    void startRecording(core::storage::Recorder& recorder) override;
    void take(const LiveTake& take) override;
    void takeZeros(const LiveTake& take) override;
    void clearLists() override { m_presses.clear(); }
    std::string storedText(const RecordingSummary& summary) const override;

    const std::shared_ptr<core::compliance::LivePalpation>& palpation() const { return m_palpation; }
    const std::vector<PressRecord>& presses() const { return m_presses; }
    // The phantom's grid of sites (none: a press is taken at the
    // recording's site) and the cell the next press is taken at; a press
    // stored moves it on. The same grid keeps its selection.
    void setSiteGrid(std::optional<core::compliance::SiteGrid> grid);
    const std::optional<core::compliance::SiteGrid>& siteGrid() const { return m_siteGrid; }
    void selectSite(core::compliance::SiteCell cell);

private:
    std::vector<core::storage::StoredCalibration> m_calibrations;
    std::shared_ptr<core::compliance::LivePalpation> m_palpation;
    std::vector<PressRecord> m_presses;
    std::vector<core::compliance::PressReading> m_later;  // stream times, after the samples recorded
    std::optional<core::compliance::SiteGrid> m_siteGrid;
};

}  // namespace tactiscope::devices::session
