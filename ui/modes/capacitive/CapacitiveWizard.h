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

#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QTimer;

namespace tactiscope::ui {

class ReferenceLink;
class SweepCapture;

class CapacitiveWizard : public CalibrationWizard {
    Q_OBJECT

public:
    explicit CapacitiveWizard(CalibrationContext context, QWidget* parent = nullptr);
    ~CapacitiveWizard() override;

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

    // The sweep against a reference force.
    struct Sweep {
        QString reference;  // "force (load cell)"
        double zero_n = 0.0;
        double span_n = 0.0;
        std::size_t turns = 0;
        double lag_s = 0.0;  // the beam's time constant, taken out
        std::size_t paired = 0;
        std::optional<double> clockUncertainty_s;
        double steepest_n_per_s = 0.0;
        std::optional<core::calibration::WindowStatistics> finalBaseline;
    };
    CheckedPage* createMethodPage();
    bool sweeping() const;
    void listReferences();
    std::size_t currentReferenceDevice() const;  // its place in m_references
    void connectReference();
    void showMethod(int page);
    void startSweep();
    void pollSweep();
    void finishSweep();
    QString sweepHtml() const;

    QRadioButton* m_bySweep = nullptr;
    QComboBox* m_reference = nullptr;
    QLineEdit* m_referencePath = nullptr;
    QLabel* m_referenceStatus = nullptr;
    QPushButton* m_finalZeroButton = nullptr;
    QPushButton* m_startSweep = nullptr;
    QPushButton* m_finishSweep = nullptr;
    QTimer* m_sweepTimer = nullptr;
    ReferenceLink* m_link = nullptr;
    // The devices a reference can be read from, as the reference box lists
    // them: this one, the session's others, the one connected for the sweep.
    std::vector<ReferenceDevice> m_references;
    std::unique_ptr<SweepCapture> m_capture;
    std::optional<Sweep> m_sweep;

    std::optional<core::calibration::WindowStatistics> m_finalZero;
    std::optional<core::calibration::CapacitiveCalibrationResult> m_result;
};

}  // namespace tactiscope::ui
