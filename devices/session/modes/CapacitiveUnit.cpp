// CapacitiveUnit: the beam's readout and its baselines.
#include "devices/session/modes/CapacitiveUnit.h"

#include "core/calibration/CalibrationRecord.h"
#include "core/storage/Recorder.h"
#include "devices/session/modes/StoredCalibrationLookup.h"

#include <stdexcept>
#include <variant>

namespace tactiscope::devices::session {

CapacitiveUnit::CapacitiveUnit(const LiveUnitSetup& setup)
{
    const auto& probe = std::get<core::sensors::CapacitiveBeamProfile>(*setup.profile);
    try {
        std::vector<core::storage::StoredCalibration> newest;
        if (auto record = newestCalibration(setup, core::calibration::kCapacitiveKind, probe.name))
            newest.push_back(std::move(*record));
        std::vector<core::calibration::CalibrationRecord> records;
        for (const auto& stored : newest) records.push_back(stored.record);
        std::optional<std::size_t> usable;
        std::string refused;
        const auto [sensitivity, drift] = core::capacitive::readoutSettings(probe, records, &usable, &refused);
        if (usable) m_calibrations.push_back(newest[*usable]);
        if (!refused.empty() && setup.refused) *setup.refused = refused;
        m_capacitive = std::make_shared<core::capacitive::LiveCapacitive>(setup.channels, setup.rate_hz, sensitivity,
                                                                          drift, setup.displaySeconds, probe.channels);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("the profile '" + probe.name + "' cannot be used: " + e.what());
    }
    if (const auto* previous = dynamic_cast<const CapacitiveUnit*>(setup.previous))
        m_capacitive->inheritBaseline(*previous->m_capacitive);
}

void CapacitiveUnit::startRecording(core::storage::Recorder& recorder)
{
    const auto baseline = m_capacitive->currentBaseline();
    recorder.addZero(baseline.firstIndex, core::capacitive::baselineJson(baseline.c0_f));
}

void CapacitiveUnit::takeZeros(const LiveTake& take)
{
    for (const auto& baseline : m_capacitive->takeBaselineChanges())
        if (take.recorder) take.recorder->addZero(baseline.firstIndex, core::capacitive::baselineJson(baseline.c0_f));
}

std::string CapacitiveUnit::storedText(const RecordingSummary&) const
{
    if (m_calibrations.empty()) return "calibration none (the beam model)";
    const auto& record = m_calibrations.front().record;
    return "calibration " + record.timestampUtc + " by " + record.operatorName;
}

}  // namespace tactiscope::devices::session
