// The capacitive mode's live part: the capacitive beam's readout through
// its profile and its newest C0 and sensitivity calibration, and the
// baselines C0 it reads on, stored with a capacitive recording.
#pragma once

#include "core/capacitive/LiveCapacitive.h"
#include "devices/session/LiveModeUnit.h"

namespace tactiscope::devices::session {

class CapacitiveUnit final : public LiveModeUnit {
public:
    // Throws std::invalid_argument for a beam or channels it cannot use.
    explicit CapacitiveUnit(const LiveUnitSetup& setup);

    std::shared_ptr<core::BlockSink> sink() const override { return m_capacitive; }
    const std::vector<core::storage::StoredCalibration>& calibrations() const override { return m_calibrations; }
    // By the names the review's derived lanes have (core/derived).
    std::vector<LiveQuantity> quantities() const override
    {
        return {{"force", "N", core::ChannelKind::Force, m_capacitive->output(), 0},
                {"deflection", "m", core::ChannelKind::Position, m_capacitive->output(), 1}};
    }
    std::optional<std::string> tare() override { return m_capacitive->tare(); }
    void startRecording(core::storage::Recorder& recorder) override;
    void take(const LiveTake&) override {}
    void takeZeros(const LiveTake& take) override;
    std::string storedText(const RecordingSummary& summary) const override;

    const std::shared_ptr<core::capacitive::LiveCapacitive>& capacitive() const { return m_capacitive; }

private:
    std::vector<core::storage::StoredCalibration> m_calibrations;
    std::shared_ptr<core::capacitive::LiveCapacitive> m_capacitive;
};

}  // namespace tactiscope::devices::session
