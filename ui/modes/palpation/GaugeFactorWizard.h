// The gauge-factor calibration wizard for one strain-gauged cantilever of
// a compliance probe (seed 001): the channel, the probe profile and which
// of its beams; the bridge, excitation, amplifier gain and ADC (prefilled
// from the beam's newest calibration); then the shared zero, known loads
// (masses in g or mgf, or known tip deflections) and result pages of
// CalibrationWizard. Accept stores a calibration record; the newest record
// of a beam is the one the palpation view uses. The fit is
// core::calibration::calibrateGaugeFactor.
#pragma once

#include "core/calibration/GaugeFactorCalibration.h"
#include "ui/calibration/CalibrationWizard.h"

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace tactiscope::ui {

class QuantityEdit;

class GaugeFactorWizard : public CalibrationWizard {
    Q_OBJECT

public:
    explicit GaugeFactorWizard(CalibrationContext context, QWidget* parent = nullptr);

    // The fit of the loads so far (two at least), as it would be stored.
    const std::optional<core::calibration::GaugeFactorResult>& result() const { return m_result; }

private:
    enum class LoadUnit { Grams, MilligramsForce, TipDeflection_mm };

    CheckedPage* createChainPage();
    void addDeviationWarning();
    void initializePage(int id) override;

    Fit fitLoads() override;
    bool sensorChosen() const override { return probe() != nullptr; }
    double forceOf(const Load& load) const override;
    QString loadText(const Load& load) const override;
    core::calibration::StabilitySettings stabilityDefaults() const override;
    std::optional<QString> refusal(const Load& load) const override;
    QString resultHtml() const override;
    void resultShown() override;
    core::calibration::CalibrationRecord record() const override;

    const core::sensors::CompliancePairProfile* probe() const;
    core::sensors::CantileverBeam beam() const;
    std::string sensorName() const;
    std::optional<core::straingauge::StrainGaugeChain> chain() const;
    void prefillChain();
    void showBeam();

    QComboBox* m_beam;

    QComboBox* m_bridge;
    QuantityEdit* m_excitation;
    QuantityEdit* m_gain;
    QSpinBox* m_bits;
    QuantityEdit* m_reference;
    QCheckBox* m_bipolar;
    QuantityEdit* m_nominal;
    QLabel* m_prefill;

    QLabel* m_deviationWarning;
    QDoubleSpinBox* m_warnPercent;
    std::optional<core::calibration::GaugeFactorResult> m_result;
};

}  // namespace tactiscope::ui
