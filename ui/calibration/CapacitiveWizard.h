// The C0 and sensitivity calibration wizard for the capacitive beam (seed
// 002): the capacitance channel and the beam's profile, then the shared
// zero (C0 and its noise σ), loads and result pages of CalibrationWizard,
// with weights placed and removed step by step (loading and unloading
// apart on the linearity plot) and an optional final zero that removes the
// drift. A credible fit gives the sensitivity, intercept, R², hysteresis
// and the detection limits in force and in displacement; Accept stores the
// record, which the capacitive view then reads with (the newest record of a
// sensor is the active one). The fit is core::calibration::calibrateCapacitive.
#pragma once

#include "core/calibration/CapacitiveCalibration.h"
#include "ui/calibration/CalibrationWizard.h"

#include <optional>

namespace tactiscope::ui {

class CapacitiveWizard : public CalibrationWizard {
    Q_OBJECT

public:
    explicit CapacitiveWizard(CalibrationContext context, QWidget* parent = nullptr);

    const std::optional<core::calibration::CapacitiveCalibrationResult>& result() const { return m_result; }

private:
    enum class Unit { MilligramsForce, Grams };

    Fit fitLoads() override;
    bool sensorChosen() const override { return profile() != nullptr; }
    double forceOf(const Load& load) const override;
    QString loadText(const Load& load) const override;
    core::calibration::StabilitySettings stabilityDefaults() const override;
    QString resultHtml() const override;
    core::calibration::CalibrationRecord record() const override;

    const core::sensors::CapacitiveBeamProfile* profile() const;
    void showBeam();
    void takeFinalZero();
    // The final zero, when it was taken after the zero the loads are
    // measured from (a final zero older than a retaken zero is stale).
    std::optional<core::calibration::WindowStatistics> finalZero() const;

    std::optional<core::calibration::WindowStatistics> m_finalZero;
    std::optional<core::calibration::CapacitiveCalibrationResult> m_result;
};

}  // namespace tactiscope::ui
