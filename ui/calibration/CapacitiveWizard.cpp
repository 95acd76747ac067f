// CapacitiveWizard: the beam's profile and the final zero around
// core::calibration::calibrateCapacitive.
#include "ui/calibration/CapacitiveWizard.h"
#include "ui/NumberText.h"

#include "core/sensors/CapacitiveBeam.h"
#include "ui/calibration/CalibrationText.h"
#include "ui/calibration/CapturePanel.h"
#include "ui/calibration/WizardText.h"

#include <QComboBox>
#include <QLocale>
#include <QPushButton>

namespace tactiscope::ui {
namespace {

using core::calibration::kMilligramForce_n;

CalibrationWizard::Words capacitiveWords()
{
    return {.zeroName = QObject::tr("C0"),
            .signal = {1e12, QObject::tr("pF"), QObject::tr("Capacitance")},
            .signalDecimals = 4,
            .channelLabel = QObject::tr("&Channel (capacitance)"),
            .channelFits = [](const core::ChannelDescriptor& c) { return c.kind == core::ChannelKind::Capacitance; },
            .noChannel = QObject::tr("<b>This device sends no capacitance channel.</b> Connect the capacitive beam, or "
                                     "the simulator's capacitive calibration rig."),
            .mode = core::Mode::Capacitive,
            .profileFits =
                [](const core::sensors::SensorProfile& p) {
                    return std::holds_alternative<core::sensors::CapacitiveBeamProfile>(p);
                },
            .zeroSubTitle = QObject::tr("Nothing on the beam. The zero, C0, and its noise σ are taken as soon as the "
                                        "capacitance is stable."),
            .loadsSubTitle =
                QObject::tr("Place weights one at a time, then take them off again. Enter the total now on "
                            "the beam and press Capture: once the capacitance is stable, the load is read "
                            "from a fresh stable window after that."),
            .loadUnits = {{QObject::tr("mgf on the beam"), 0}, {QObject::tr("g on the beam"), 1}},
            .firstLoad = {30.0, 0},
            .plotX = {1e3, QObject::tr("mN"), QObject::tr("Force")},
            .plotY = {1e12, QObject::tr("pF"), QObject::tr("ΔC")},
            .resultSubTitle =
                QObject::tr("Accept stores the calibration; the capacitive view then reads this beam through it."),
            .limits = core::calibration::capacitiveCredibilityLimits()};
}

}  // namespace

CapacitiveWizard::CapacitiveWizard(CalibrationContext context, QWidget* parent)
    : CalibrationWizard(std::move(context), capacitiveWords(), parent)
{
    static_assert(static_cast<int>(Unit::Grams) == 1, "the load unit ids of capacitiveWords()");
    setWindowTitle(tr("Capacitive beam calibration (C0 and sensitivity)"));
    setObjectName(QStringLiteral("capacitiveWizard"));
    addPages({});
    auto* finalZero = new QPushButton(tr("&Final zero (all off)"));
    finalZero->setObjectName(QStringLiteral("finalZeroButton"));
    finalZero->setToolTip(tr("A second zero after the last weight is off: the drift between the two is taken out of "
                             "every load."));
    panel()->addButton(finalZero);
    connect(finalZero, &QPushButton::clicked, this, &CapacitiveWizard::takeFinalZero);
    connect(profileBox(), &QComboBox::currentIndexChanged, this, &CapacitiveWizard::showBeam);
    showBeam();
}

const core::sensors::CapacitiveBeamProfile* CapacitiveWizard::profile() const
{
    return chosenProfile<core::sensors::CapacitiveBeamProfile>();
}

void CapacitiveWizard::showBeam()
{
    if (!profile()) return;
    const core::sensors::CapacitiveBeam beam(profile()->geometry);
    setSensorSummary(tr("The beam model expects C0 = %1 pF, %2 pF/mN and k = %3 N/m: the calibration measures the "
                        "first two on the real beam.")
                         .arg(significant(profile()->geometry.c0_f * 1e12),
                              significant(beam.capacitancePerNewton_f_per_n() * 1e9),
                              significant(beam.stiffness_n_per_m())));
}

void CapacitiveWizard::takeFinalZero()
{
    if (context().rig) context().rig->place(0.0);
    waitForWindow(tr("Waiting for a stable zero with every weight off…"),
                  [this](const core::calibration::WindowStatistics& window) {
                      m_finalZero = window;
                      panel()->setWaiting(false);
                      panel()->setStatus(tr("Final zero %1 pF: the drift since C0 is taken out of every load.")
                                             .arg(fixedText(window.mean * 1e12, 4)));
                      refit();
                      panel()->focusEntry();
                  });
}

std::optional<core::calibration::WindowStatistics> CapacitiveWizard::finalZero() const
{
    if (m_finalZero && zero() && m_finalZero->start_s > zero()->end_s) return m_finalZero;
    return std::nullopt;
}

core::calibration::StabilitySettings CapacitiveWizard::stabilityDefaults() const
{
    return core::calibration::capacitiveStabilityDefaults();
}

double CapacitiveWizard::forceOf(const Load& load) const
{
    return static_cast<Unit>(load.unit) == Unit::Grams ? load.value * 1e3 * kMilligramForce_n
                                                       : load.value * kMilligramForce_n;
}

QString CapacitiveWizard::loadText(const Load& load) const
{
    return static_cast<Unit>(load.unit) == Unit::Grams ? tr("%1 g").arg(typedText(load.value))
                                                       : tr("%1 mgf").arg(typedText(load.value));
}

CalibrationWizard::Fit CapacitiveWizard::fitLoads()
{
    core::calibration::CapacitiveCalibrationInput input;
    input.baseline = *zero();
    input.finalBaseline = finalZero();
    input.stiffness_n_per_m = core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m();
    for (const Load& load : loads())
        input.steps.push_back({forceOf(load), std::nullopt, load.window.mean, load.window.middle_s(), load.loading});
    m_result = core::calibration::calibrateCapacitive(input, profile()->name, operatorName().toStdString());
    const auto& fit = *m_result->forceFit;
    const auto [sensitivity, error] = valueAndErrorTexts(fit.slope * 1e9, fit.slopeStandardError * 1e9);
    return {m_result->fitForce_n, m_result->fitDelta_f, fit,
            tr("Sensitivity %1 ± %2 pF/mN, R² = %3, %4 points with the zero.")
                .arg(sensitivity, error, fixedText(fit.rSquared, 6))
                .arg(fit.points)};
}

QString CapacitiveWizard::resultHtml() const
{
    const QLocale locale;
    const auto& r = *m_result;
    const auto& fit = *r.forceFit;
    const QString drift =
        finalZero() ? tr("drift %1 pF/min (removed from every load)").arg(fixedText(r.drift_f_per_s * 1e12 * 60.0, 4))
                    : tr("no final zero, so no drift correction");
    const QString hysteresis = r.hysteresis ? tr("%1 % of full scale").arg(fixedText(*r.hysteresis * 100, 2))
                                            : tr("not measured (no load was both placed and removed)");
    const auto [sensitivity, error] = valueAndErrorTexts(fit.slope * 1e9, fit.slopeStandardError * 1e9);
    QString cautions;
    for (const std::string& caution : r.cautions)
        cautions += QStringLiteral("<br><span style=\"color:#b00020\">%1</span>")
                        .arg(tr("Caution: %1.").arg(QString::fromStdString(caution)).toHtmlEscaped());
    return tr("<b>%1</b><br>C0 = <b>%2 pF</b>, noise σ %3 pF; %4.<br>Sensitivity <b>%5 ± %6 pF/mN</b> (standard "
              "uncertainty, k = 1, from the points' scatter), intercept %7 pF, R² = %8; relative sensitivity %9 "
              "per mN.<br>Hysteresis %10.<br>Detection limit (3σ): %11, a tip displacement of %12 through k = %13 "
              "N/m.")
               .arg(QString::fromStdString(profile()->name).toHtmlEscaped(), fixedText(r.c0_f * 1e12, 4),
                    fixedText(r.baselineSigma_f * 1e12, 4), drift, sensitivity, error,
                    fixedText(fit.intercept * 1e12, 4), fixedText(fit.rSquared, 6),
                    significant(*r.relativeSensitivity_per_n * 1e-3, 3))
               .arg(hysteresis, detectionLimitText(*r.detectionLimit_n),
                    siText(r.detectionLimit_m.value_or(0), QStringLiteral("m"), 3),
                    significant(core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m(), 3)) +
           cautions;
}

core::calibration::CalibrationRecord CapacitiveWizard::record() const
{
    core::calibration::CalibrationRecord record = m_result->record;
    record.values.emplace_back("sensitivity_standard_error_pf_per_mn", m_result->forceFit->slopeStandardError * 1e9);
    return record;
}

}  // namespace tactiscope::ui
