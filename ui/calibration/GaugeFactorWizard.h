// The gauge-factor calibration wizard for one strain-gauged cantilever of
// a compliance probe (seed 001): choose the channel, the probe profile and
// which of its beams; set the bridge, excitation, amplifier gain and ADC;
// take the zero once the signal is stable; hang known loads (masses in g or
// mgf, or known tip deflections) one by one, each read as the mean of a
// stable window; see the points, the fitted line and the residuals as they
// come; and accept a credible fit, which stores a calibration record (the
// newest record of a beam is the one the palpation view uses). Cancel
// stores nothing. The fit is core::calibration::calibrateGaugeFactor.
#pragma once

#include "core/calibration/GaugeFactorCalibration.h"
#include "core/calibration/StabilityMonitor.h"
#include "ui/ProfileLibrary.h"
#include "ui/calibration/CalibrationContext.h"

#include <QWizard>

#include <cstdint>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace tactiscope::ui {

class CapturePanel;
class CheckedPage;
class FitLimitsBox;
class QuantityEdit;
class StabilityCriteria;
class StabilityWatch;

class GaugeFactorWizard : public QWizard {
    Q_OBJECT

public:
    enum Page { ChannelPage, ChainPage, ZeroPage, LoadsPage, ResultPage };

    explicit GaugeFactorWizard(CalibrationContext context, QWidget* parent = nullptr);

    // The fit of the points so far (two loads at least), as it would be stored.
    const std::optional<core::calibration::GaugeFactorResult>& result() const { return m_result; }
    bool credible() const;

    void accept() override;

signals:
    void calibrationStored(std::int64_t id, const QString& sensor);

private:
    enum class LoadUnit { Grams, MilligramsForce, TipDeflection_mm };
    struct LoadPoint {
        double value = 0.0;
        LoadUnit unit = LoadUnit::Grams;
        core::calibration::WindowStatistics window;
    };

    CheckedPage* createChannelPage();
    CheckedPage* createChainPage();
    CheckedPage* createZeroPage();
    CheckedPage* createLoadsPage();
    CheckedPage* createResultPage();
    void initializePage(int id) override;
    void cleanupPage(int id) override;

    const core::sensors::CompliancePairProfile* probe() const;
    core::sensors::CantileverBeam beam() const;
    std::string sensorName() const;
    std::optional<core::straingauge::StrainGaugeChain> chain() const;
    void prefillChain();
    void applyStabilityDefaults();
    void applyStabilitySettings();
    void showBeam();

    void takeZero();
    void capture();
    void captured(const core::calibration::WindowStatistics& window);
    void retake(int row);
    void remove(int row);
    QString loadText(const LoadPoint& point) const;
    core::calibration::CalibrationLoad loadOf(const LoadPoint& point) const;
    double forceOf(double value, LoadUnit unit) const;  // what the rig hangs
    void refit();
    void showResult();
    QString pointName(std::size_t fitted) const;

    CalibrationContext m_context;
    std::vector<ProfileEntry> m_probes;
    StabilityWatch* m_watch;

    QComboBox* m_channel;
    QComboBox* m_probe;
    QComboBox* m_beam;
    QLineEdit* m_operator;
    QLabel* m_beamSummary;

    QComboBox* m_bridge;
    QuantityEdit* m_excitation;
    QuantityEdit* m_gain;
    QSpinBox* m_bits;
    QuantityEdit* m_reference;
    QCheckBox* m_bipolar;
    QuantityEdit* m_nominal;
    QLabel* m_prefill;

    StabilityCriteria* m_criteria;
    QLabel* m_zeroText;
    std::optional<core::calibration::WindowStatistics> m_zero;

    CapturePanel* m_panel;
    std::vector<LoadPoint> m_points;
    std::optional<LoadPoint> m_pending;        // waiting for its stable window
    std::optional<std::size_t> m_retakeIndex;  // the point the pending one replaces

    QLabel* m_resultText;
    QLabel* m_deviationWarning;
    QLabel* m_problems;
    QDoubleSpinBox* m_warnPercent;
    FitLimitsBox* m_limits;
    std::optional<core::calibration::GaugeFactorResult> m_result;
};

}  // namespace tactiscope::ui
