// CapacitiveWizard: four pages around core::calibration::calibrateCapacitive.
#include "ui/calibration/CapacitiveWizard.h"

#include "core/calibration/FitCredibility.h"
#include "core/sensors/CapacitiveBeam.h"
#include "core/storage/Database.h"
#include "ui/ActiveProfiles.h"
#include "ui/calibration/CalibrationPlot.h"
#include "ui/calibration/CapturePanel.h"
#include "ui/calibration/CheckedPage.h"
#include "ui/calibration/FitLimitsBox.h"
#include "ui/calibration/StabilityCriteria.h"
#include "ui/calibration/StabilityIndicator.h"
#include "ui/calibration/StabilityWatch.h"
#include "ui/calibration/StoredCalibrations.h"
#include "ui/calibration/WizardText.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

using core::calibration::kMilligramForce_n;

const DisplayUnit kPicofarad{1e12, QStringLiteral("pF"), QStringLiteral("Capacitance")};

// A hysteresis of the soft silicone of a few per cent of full scale is the
// sensor's, not a bad point: the default allows for it.
core::calibration::CredibilityLimits capacitiveLimits()
{
    core::calibration::CredibilityLimits limits;
    limits.maximumOffLine = 0.03;
    return limits;
}

}  // namespace

CapacitiveWizard::CapacitiveWizard(CalibrationContext context, QWidget* parent)
    : QWizard(parent),
      m_context(std::move(context)),
      m_watch(new StabilityWatch(this))
{
    setWindowTitle(tr("Capacitive beam calibration (C0 and sensitivity)"));
    setObjectName(QStringLiteral("capacitiveWizard"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    setButtonText(QWizard::FinishButton, tr("&Accept and store"));
    for (const ProfileEntry& entry : ProfileLibrary(m_context.profileDirectory)
                                         .entries(QStringLiteral("capacitive"), activeProfile("capacitive").path))
        if (entry.profile && std::holds_alternative<core::sensors::CapacitiveBeamProfile>(*entry.profile))
            m_profiles.push_back(entry);
    setPage(SensorPage, createSensorPage());
    setPage(BaselinePage, createBaselinePage());
    setPage(StepsPage, createStepsPage());
    setPage(ResultPage, createResultPage());
    connect(m_watch, &StabilityWatch::captured, this, &CapacitiveWizard::captured);
    resize(1000, 680);
}

void CapacitiveWizard::recheck(int id)
{
    static_cast<CheckedPage*>(page(id))->recheck();
}

CheckedPage* CapacitiveWizard::createSensorPage()
{
    auto* page = new CheckedPage([this] { return m_channel->currentIndex() >= 0 && profile(); });
    page->setTitle(tr("Channel and sensor"));
    page->setSubTitle(tr("Which capacitance channel, on which beam."));
    m_channel = new QComboBox(page);
    m_channel->setObjectName(QStringLiteral("channelBox"));
    for (std::size_t c = 0; c < m_context.channels.size(); ++c)
        if (m_context.channels[c].kind == core::ChannelKind::Capacitance)
            m_channel->addItem(QString::fromStdString(m_context.channels[c].name), static_cast<qulonglong>(c));
    m_profile = new QComboBox(page);
    m_profile->setObjectName(QStringLiteral("profileBox"));
    for (const ProfileEntry& entry : m_profiles) m_profile->addItem(entry.name, entry.path);
    m_operator = new QLineEdit(m_context.operatorName, page);
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_operator->setPlaceholderText(tr("who calibrates (stored with the record)"));
    m_beamSummary = wrappedLabel({}, page);
    auto* form = new QFormLayout;
    form->addRow(tr("&Channel (capacitance)"), m_channel);
    form->addRow(tr("&Sensor profile"), m_profile);
    form->addRow(tr("&Operator"), m_operator);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(m_beamSummary);
    if (m_channel->count() == 0)
        layout->addWidget(wrappedLabel(tr("<b>This device sends no capacitance channel.</b> Connect the capacitive "
                                          "beam, or the simulator's capacitive calibration rig."),
                                       page));
    layout->addStretch();
    connect(m_profile, &QComboBox::currentIndexChanged, this, &CapacitiveWizard::showBeam);
    showBeam();
    return page;
}

CheckedPage* CapacitiveWizard::createBaselinePage()
{
    auto* page = new CheckedPage([this] { return m_baseline.has_value(); });
    page->setTitle(tr("Baseline (C0)"));
    page->setSubTitle(tr("Nothing on the beam. C0 and its noise σ are taken as soon as the capacitance is stable."));
    auto* indicator = new StabilityIndicator(m_watch, page);
    indicator->setUnit(kPicofarad);
    m_criteria = new StabilityCriteria(kPicofarad, page);
    m_criteria->setSettings({2.0, 0.005e-12, 0.02e-12});
    m_baselineText = new QLabel(page);
    m_baselineText->setObjectName(QStringLiteral("baselineText"));
    auto* retake = new QPushButton(tr("Re&take baseline"), page);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(indicator);
    layout->addWidget(m_criteria);
    layout->addWidget(m_baselineText);
    layout->addWidget(retake, 0, Qt::AlignLeft);
    layout->addStretch();
    connect(m_criteria, &StabilityCriteria::edited, this, [this] {
        m_watch->setSettings(m_criteria->settings());
        if (!m_baseline) takeBaseline();
    });
    connect(retake, &QPushButton::clicked, this, &CapacitiveWizard::takeBaseline);
    return page;
}

CheckedPage* CapacitiveWizard::createStepsPage()
{
    auto* page = new CheckedPage([this] { return m_result.has_value() && m_capturing == Capture::None; });
    page->setTitle(tr("Weights on and off"));
    page->setSubTitle(tr("Place weights one step at a time, then take them off again. Enter the total now on the "
                         "beam and press Capture: the step is the first stable window after that."));
    m_panel = new CapturePanel(m_watch, kPicofarad,
                               {{tr("mgf on the beam"), static_cast<int>(Unit::MilligramsForce)},
                                {tr("g on the beam"), static_cast<int>(Unit::Grams)}},
                               {tr("Load"), tr("Direction"), tr("C (pF)"), tr("σ (pF)"), tr("Residual (% FS)")}, page);
    m_panel->setLoad(30.0, static_cast<int>(Unit::MilligramsForce));
    m_panel->setStatus(m_context.rig ? tr("Simulator: the rig places and removes the weights for you.") : QString());
    m_panel->plot()->setTitles(tr("Force (mN)"), tr("ΔC (pF)"), tr("Residual (pF)"));
    m_panel->plot()->setSeriesNames(tr("loading"), tr("unloading"));
    auto* finalBaseline = new QPushButton(tr("&Final baseline (all off)"));
    finalBaseline->setObjectName(QStringLiteral("finalBaselineButton"));
    finalBaseline->setToolTip(tr("A second baseline after the last weight is off: the drift between the two is taken "
                                 "out of every step."));
    m_panel->addButton(finalBaseline);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_panel);
    connect(m_panel, &CapturePanel::captureRequested, this, &CapacitiveWizard::captureStep);
    connect(m_panel, &CapturePanel::retakeRequested, this, &CapacitiveWizard::retake);
    connect(m_panel, &CapturePanel::removeRequested, this, &CapacitiveWizard::remove);
    connect(finalBaseline, &QPushButton::clicked, this, &CapacitiveWizard::takeFinalBaseline);
    return page;
}

CheckedPage* CapacitiveWizard::createResultPage()
{
    auto* page = new CheckedPage([this] { return credible(); });
    page->setTitle(tr("Result"));
    page->setSubTitle(tr("Accept stores the calibration; the capacitive view then reads this beam through it."));
    m_resultText = wrappedLabel({}, page);
    m_resultText->setObjectName(QStringLiteral("resultText"));
    m_resultText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problems = wrappedLabel({}, page);
    m_problems->setObjectName(QStringLiteral("problemsText"));
    m_problems->setStyleSheet(QStringLiteral("color: #b00020"));
    m_limits = new FitLimitsBox(capacitiveLimits(), page);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_resultText);
    layout->addWidget(m_problems);
    layout->addWidget(m_limits);
    layout->addStretch();
    connect(m_limits, &FitLimitsBox::changed, this, &CapacitiveWizard::showResult);
    return page;
}

void CapacitiveWizard::initializePage(int id)
{
    if (id == BaselinePage) {
        m_watch->setInput(m_context.buffer, m_channel->currentData().toULongLong());
        m_watch->setSettings(m_criteria->settings());
        takeBaseline();
    }
    if (id == StepsPage) refit();
    if (id == ResultPage) showResult();
    QWizard::initializePage(id);
}

void CapacitiveWizard::cleanupPage(int id)
{
    if (id == StepsPage || id == BaselinePage) {
        m_watch->disarm();
        m_capturing = Capture::None;
        m_pending.reset();
        m_panel->setWaiting(false);
    }
    QWizard::cleanupPage(id);
}

const core::sensors::CapacitiveBeamProfile* CapacitiveWizard::profile() const
{
    const int index = m_profile->currentIndex();
    if (index < 0 || index >= static_cast<int>(m_profiles.size())) return nullptr;
    return &std::get<core::sensors::CapacitiveBeamProfile>(*m_profiles[static_cast<std::size_t>(index)].profile);
}

void CapacitiveWizard::showBeam()
{
    if (!profile()) {
        m_beamSummary->setText(tr("No capacitive-beam profile can be read."));
        return;
    }
    const core::sensors::CapacitiveBeam beam(profile()->geometry);
    m_beamSummary->setText(tr("The beam model expects C0 = %1 pF, %2 pF/mN and k = %3 N/m: the calibration measures "
                              "the first two on the real beam.")
                               .arg(significant(profile()->geometry.c0_f * 1e12),
                                    significant(beam.capacitancePerNewton_f_per_n() * 1e9),
                                    significant(beam.stiffness_n_per_m())));
}

void CapacitiveWizard::takeBaseline()
{
    if (m_context.rig) m_context.rig->place(0.0);
    m_baseline.reset();
    m_baselineText->setText(tr("C0: waiting for a stable baseline…"));
    m_capturing = Capture::Baseline;
    m_watch->arm();
    recheck(BaselinePage);
}

void CapacitiveWizard::takeFinalBaseline()
{
    if (m_context.rig) m_context.rig->place(0.0);
    m_capturing = Capture::FinalBaseline;
    m_panel->setStatus(tr("Waiting for a stable baseline with every weight off…"));
    m_panel->setWaiting(true);
    m_watch->arm();
    recheck(StepsPage);
}

double CapacitiveWizard::forceOf(const Step& step) const
{
    return step.unit == Unit::Grams ? step.value * 1e3 * kMilligramForce_n : step.value * kMilligramForce_n;
}

QString CapacitiveWizard::loadText(const Step& step) const
{
    return step.unit == Unit::Grams ? tr("%1 g").arg(significant(step.value, 6))
                                    : tr("%1 mgf").arg(significant(step.value, 6));
}

void CapacitiveWizard::captureStep()
{
    Step step{m_panel->loadValue(), static_cast<Unit>(m_panel->loadUnit()), true, {}};
    if (m_retakeIndex) {
        step.loading = m_steps[*m_retakeIndex].loading;
    } else if (!m_steps.empty()) {
        // Loading while the total grows; unloading once weights come off.
        step.loading = forceOf(step) > forceOf(m_steps.back());
    }
    m_pending = step;
    if (m_context.rig) m_context.rig->place(forceOf(step));
    m_capturing = Capture::Step;
    m_panel->setStatus(tr("Waiting for a stable reading with %1…").arg(loadText(step)));
    m_panel->setWaiting(true);
    m_watch->arm();
    recheck(StepsPage);
}

void CapacitiveWizard::captured(const core::calibration::WindowStatistics& window)
{
    const QLocale locale;
    switch (std::exchange(m_capturing, Capture::None)) {
    case Capture::None:
        return;
    case Capture::Baseline:
        m_baseline = window;
        m_finalBaseline.reset();  // a drift is measured from this baseline on
        m_baselineText->setText(
            tr("C0 = %1 pF, noise σ %2 pF (mean of %3 samples)")
                .arg(locale.toString(window.mean * 1e12, 'f', 4), locale.toString(window.sigma * 1e12, 'f', 4))
                .arg(window.count));
        recheck(BaselinePage);
        return;
    case Capture::FinalBaseline:
        m_finalBaseline = window;
        m_panel->setStatus(tr("Final baseline %1 pF: the drift since C0 is taken out of every step.")
                               .arg(locale.toString(window.mean * 1e12, 'f', 4)));
        break;
    case Capture::Step: {
        Step step = *m_pending;
        step.window = window;
        if (m_retakeIndex && *m_retakeIndex < m_steps.size())
            m_steps[*m_retakeIndex] = step;
        else
            m_steps.push_back(step);
        m_panel->setStatus(tr("Captured %1: %2 pF ± %3 pF.")
                               .arg(loadText(step), locale.toString(window.mean * 1e12, 'f', 4),
                                    locale.toString(window.sigma * 1e12, 'f', 4)));
        break;
    }
    }
    m_pending.reset();
    m_retakeIndex.reset();
    m_panel->setWaiting(false);
    refit();
    m_panel->focusEntry();
}

void CapacitiveWizard::retake(int row)
{
    const Step& step = m_steps.at(static_cast<std::size_t>(row));
    m_panel->setLoad(step.value, static_cast<int>(step.unit));
    m_retakeIndex = static_cast<std::size_t>(row);
    captureStep();
}

void CapacitiveWizard::remove(int row)
{
    m_steps.erase(m_steps.begin() + row);
    refit();
}

QString CapacitiveWizard::pointName(std::size_t fitted) const
{
    if (fitted == 0) return tr("The baseline");
    const Step& step = m_steps[fitted - 1];
    return tr("Step %1 (%2, %3)").arg(fitted).arg(loadText(step), step.loading ? tr("loading") : tr("unloading"));
}

void CapacitiveWizard::refit()
{
    m_result.reset();
    if (m_baseline && m_steps.size() >= 2) {
        core::calibration::CapacitiveCalibrationInput input;
        input.baseline = *m_baseline;
        input.finalBaseline = m_finalBaseline;
        input.stiffness_n_per_m = core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m();
        for (const Step& step : m_steps)
            input.steps.push_back(
                {forceOf(step), std::nullopt, step.window.mean, step.window.middle_s(), step.loading});
        try {
            m_result = core::calibration::calibrateCapacitive(input, profile()->name,
                                                              m_operator->text().trimmed().toStdString());
        } catch (const std::invalid_argument& e) {
            m_panel->setFitSummary(tr("No fit: %1").arg(QString::fromStdString(e.what())));
        }
    }

    const QLocale locale;
    const auto& delta = m_result ? m_result->fitDelta_f : std::vector<double>{};
    const double span =
        delta.empty() ? 0.0
                      : *std::max_element(delta.begin(), delta.end()) - *std::min_element(delta.begin(), delta.end());
    std::vector<QStringList> rows;
    for (std::size_t i = 0; i < m_steps.size(); ++i) {
        const Step& step = m_steps[i];
        const bool fitted = m_result && span > 0.0;
        rows.push_back({loadText(step), step.loading ? tr("loading") : tr("unloading"),
                        locale.toString(step.window.mean * 1e12, 'f', 4),
                        locale.toString(step.window.sigma * 1e12, 'f', 4),
                        fitted ? locale.toString(100.0 * m_result->forceFit->residuals[i + 1] / span, 'f', 2)
                               : QStringLiteral("–")});
    }
    m_panel->setRows(rows, 2);

    std::vector<CalibrationPoint> points;
    if (m_result) {
        for (std::size_t i = 0; i < m_result->fitForce_n.size(); ++i)
            points.push_back(
                {m_result->fitForce_n[i] * 1e3, m_result->fitDelta_f[i] * 1e12, i == 0 || m_steps[i - 1].loading});
        const auto& fit = *m_result->forceFit;
        m_panel->plot()->setData(points, std::make_pair(fit.slope * 1e9, fit.intercept * 1e12));
        m_panel->setFitSummary(tr("Sensitivity %1 ± %2 pF/mN, R² = %3, %4 points with the baseline.")
                                   .arg(significant(fit.slope * 1e9, 5), significant(fit.slopeStandardError * 1e9, 2),
                                        locale.toString(fit.rSquared, 'f', 6))
                                   .arg(fit.points));
    } else {
        m_panel->plot()->setData(points, std::nullopt);
        if (m_steps.size() < 2) m_panel->setFitSummary(tr("Two steps are needed for a line."));
    }
    recheck(StepsPage);
}

bool CapacitiveWizard::credible() const
{
    return m_result &&
           core::calibration::judgeFit(m_result->fitForce_n, m_result->fitDelta_f, m_limits->limits()).credible();
}

void CapacitiveWizard::showResult()
{
    if (!m_result) return;
    const QLocale locale;
    const auto& r = *m_result;
    const auto& fit = *r.forceFit;
    const QString drift = m_finalBaseline ? tr("drift %1 pF/min (removed from every step)")
                                                .arg(locale.toString(r.drift_f_per_s * 1e12 * 60.0, 'f', 4))
                                          : tr("no final baseline, so no drift correction");
    const QString hysteresis = r.hysteresis ? tr("%1 % of full scale").arg(locale.toString(*r.hysteresis * 100, 'f', 2))
                                            : tr("not measured (no step was both loaded and unloaded)");
    m_resultText->setText(
        tr("<b>%1</b><br>C0 = <b>%2 pF</b>, noise σ %3 pF; %4.<br>Sensitivity <b>%5 ± %6 pF/mN</b> (standard "
           "error), intercept %7 pF, R² = %8; relative sensitivity %9 per mN.<br>Hysteresis %10.<br>Detection limit "
           "(3σ): %11 µN (%12 mgf), a tip displacement of %13 µm through k = %14 N/m.")
            .arg(QString::fromStdString(profile()->name).toHtmlEscaped(), locale.toString(r.c0_f * 1e12, 'f', 4),
                 locale.toString(r.baselineSigma_f * 1e12, 'f', 4), drift, significant(fit.slope * 1e9, 5),
                 significant(fit.slopeStandardError * 1e9, 2), locale.toString(fit.intercept * 1e12, 'f', 4),
                 locale.toString(fit.rSquared, 'f', 6), significant(*r.relativeSensitivity_per_n * 1e-3, 3))
            .arg(hysteresis, significant(*r.detectionLimit_n * 1e6, 3),
                 significant(*r.detectionLimit_n / kMilligramForce_n, 3),
                 significant(r.detectionLimit_m.value_or(0) * 1e6, 3),
                 significant(core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m(), 3)));
    const auto limits = m_limits->limits();
    const QStringList problems = FitLimitsBox::problems(core::calibration::judgeFit(r.fitForce_n, r.fitDelta_f, limits),
                                                        limits, [this](std::size_t i) { return pointName(i); });
    m_problems->setText(problems.isEmpty() ? QString()
                                           : tr("Cannot be stored: %1").arg(problems.join(QLatin1Char(' '))));
    recheck(ResultPage);
}

void CapacitiveWizard::accept()
{
    if (!credible()) return;
    core::calibration::CalibrationRecord record = m_result->record;
    record.operatorName = m_operator->text().trimmed().toStdString();
    record.timestampUtc = core::calibration::utcTimestampNow();
    record.values.emplace_back("sensitivity_standard_error_pf_per_mn", m_result->forceFit->slopeStandardError * 1e9);
    const auto id = storeCalibrationOrSay(this, m_context.storePath, record);
    if (!id) return;
    m_watch->disarm();
    emit calibrationStored(*id, QString::fromStdString(record.sensorName));
    QWizard::accept();
}

}  // namespace tactiscope::ui
