// The C0 and sensitivity calibration wizard for the capacitive beam (seed
// 002): choose the capacitance channel and the beam's profile; take the
// unloaded baseline once it is stable (C0 and its noise σ); place and
// remove weights step by step, each read as the mean of a stable window,
// with the linearity plot (loading and unloading apart) and its residuals
// as they come; an optional final baseline removes the drift. A credible
// fit gives the sensitivity, intercept, R², hysteresis and the detection
// limits in force and in displacement; accept stores the record, which the
// capacitive view then reads with (the newest record of a sensor is the
// active one). Cancel stores nothing. The fit is
// core::calibration::calibrateCapacitive.
#pragma once

#include "core/calibration/CapacitiveCalibration.h"
#include "ui/ProfileLibrary.h"
#include "ui/calibration/CalibrationContext.h"

#include <QWizard>

#include <cstdint>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tactiscope::ui {

class CapturePanel;
class CheckedPage;
class FitLimitsBox;
class StabilityCriteria;
class StabilityWatch;

class CapacitiveWizard : public QWizard {
    Q_OBJECT

public:
    enum Page { SensorPage, BaselinePage, StepsPage, ResultPage };

    explicit CapacitiveWizard(CalibrationContext context, QWidget* parent = nullptr);

    const std::optional<core::calibration::CapacitiveCalibrationResult>& result() const { return m_result; }
    bool credible() const;

    void accept() override;

signals:
    void calibrationStored(std::int64_t id, const QString& sensor);

private:
    enum class Unit { MilligramsForce, Grams };
    struct Step {
        double value = 0.0;  // total load on the beam, in `unit`
        Unit unit = Unit::MilligramsForce;
        bool loading = true;
        core::calibration::WindowStatistics window;
    };
    // What the watch's next stable window is for.
    enum class Capture { None, Baseline, FinalBaseline, Step };

    CheckedPage* createSensorPage();
    CheckedPage* createBaselinePage();
    CheckedPage* createStepsPage();
    CheckedPage* createResultPage();
    void initializePage(int id) override;
    void cleanupPage(int id) override;

    const core::sensors::CapacitiveBeamProfile* profile() const;
    void showBeam();
    void takeBaseline();
    void takeFinalBaseline();
    void captureStep();
    void captured(const core::calibration::WindowStatistics& window);
    void retake(int row);
    void remove(int row);
    double forceOf(const Step& step) const;
    QString loadText(const Step& step) const;
    QString pointName(std::size_t fitted) const;
    void refit();
    void showResult();
    void recheck(int page);

    CalibrationContext m_context;
    std::vector<ProfileEntry> m_profiles;
    StabilityWatch* m_watch;
    Capture m_capturing = Capture::None;

    QComboBox* m_channel;
    QComboBox* m_profile;
    QLineEdit* m_operator;
    QLabel* m_beamSummary;

    StabilityCriteria* m_criteria;
    QLabel* m_baselineText;
    std::optional<core::calibration::WindowStatistics> m_baseline;

    CapturePanel* m_panel;
    std::vector<Step> m_steps;
    std::optional<Step> m_pending;
    std::optional<std::size_t> m_retakeIndex;
    std::optional<core::calibration::WindowStatistics> m_finalBaseline;

    QLabel* m_resultText;
    QLabel* m_problems;
    FitLimitsBox* m_limits;
    std::optional<core::calibration::CapacitiveCalibrationResult> m_result;
};

}  // namespace tactiscope::ui
