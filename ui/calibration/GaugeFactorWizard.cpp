// GaugeFactorWizard: five pages around core::calibration::calibrateGaugeFactor.
#include "ui/calibration/GaugeFactorWizard.h"

#include "core/calibration/FitCredibility.h"
#include "core/storage/Database.h"
#include "core/storage/SessionStore.h"
#include "ui/ActiveProfiles.h"
#include "ui/QuantityEdit.h"
#include "ui/calibration/CalibrationPlot.h"
#include "ui/calibration/CapturePanel.h"
#include "ui/calibration/CheckedPage.h"
#include "ui/calibration/FitLimitsBox.h"
#include "ui/calibration/StabilityCriteria.h"
#include "ui/calibration/StabilityIndicator.h"
#include "ui/calibration/StabilityWatch.h"
#include "ui/calibration/StoredCalibrations.h"
#include "ui/calibration/WizardText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::ui {
namespace {

using core::calibration::kStandardGravity_m_per_s2;
using core::straingauge::BridgeType;

bool inCounts(const core::ChannelDescriptor& channel)
{
    return channel.unit == "count" || channel.unit == "counts";
}

// A bridge is stored as its number of active gauges: a physical count
// rather than a code (quarter 1, half 2, full 4).
double activeGauges(BridgeType type)
{
    return type == BridgeType::Quarter ? 1.0 : type == BridgeType::HalfBending ? 2.0 : 4.0;
}

BridgeType bridgeOfGauges(double gauges)
{
    return gauges < 1.5 ? BridgeType::Quarter : gauges < 3.0 ? BridgeType::HalfBending : BridgeType::FullBending;
}

}  // namespace

GaugeFactorWizard::GaugeFactorWizard(CalibrationContext context, QWidget* parent)
    : QWizard(parent),
      m_context(std::move(context)),
      m_watch(new StabilityWatch(this))
{
    setWindowTitle(tr("Gauge-factor calibration"));
    setObjectName(QStringLiteral("gaugeFactorWizard"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    setButtonText(QWizard::FinishButton, tr("&Accept and store"));
    for (const ProfileEntry& entry : ProfileLibrary(m_context.profileDirectory)
                                         .entries(QStringLiteral("palpation"), activeProfile("palpation").path))
        if (entry.profile && std::holds_alternative<core::sensors::CompliancePairProfile>(*entry.profile))
            m_probes.push_back(entry);

    setPage(ChannelPage, createChannelPage());
    setPage(ChainPage, createChainPage());
    setPage(ZeroPage, createZeroPage());
    setPage(LoadsPage, createLoadsPage());
    setPage(ResultPage, createResultPage());
    connect(m_watch, &StabilityWatch::captured, this, [this](const core::calibration::WindowStatistics& window) {
        if (currentId() == ZeroPage) {
            m_zero = window;
            m_zeroText->setText(tr("Zero: %1 counts, σ %2 counts (mean of %3 samples)")
                                    .arg(significant(window.mean, 6), significant(window.sigma, 3))
                                    .arg(window.count));
            refit();
            static_cast<CheckedPage*>(page(ZeroPage))->recheck();
        } else {
            captured(window);
        }
    });
    resize(980, 660);
}

CheckedPage* GaugeFactorWizard::createChannelPage()
{
    auto* page = new CheckedPage([this] { return m_channel->currentIndex() >= 0 && probe(); });
    page->setTitle(tr("Channel and sensor"));
    page->setSubTitle(tr("Which bridge channel, on which beam of which probe."));
    m_channel = new QComboBox(page);
    m_channel->setObjectName(QStringLiteral("channelBox"));
    for (std::size_t c = 0; c < m_context.channels.size(); ++c)
        if (inCounts(m_context.channels[c]))
            m_channel->addItem(QString::fromStdString(m_context.channels[c].name), static_cast<qulonglong>(c));
    m_probe = new QComboBox(page);
    m_probe->setObjectName(QStringLiteral("probeBox"));
    for (const ProfileEntry& entry : m_probes) m_probe->addItem(entry.name, entry.path);
    m_beam = new QComboBox(page);
    m_beam->setObjectName(QStringLiteral("beamBox"));
    m_beam->addItems({tr("stiff beam (F_H)"), tr("soft beam (F_L)")});
    m_operator = new QLineEdit(m_context.operatorName, page);
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_operator->setPlaceholderText(tr("who calibrates (stored with the record)"));
    m_beamSummary = wrappedLabel({}, page);

    auto* form = new QFormLayout;
    form->addRow(tr("&Channel (ADC counts)"), m_channel);
    form->addRow(tr("&Probe"), m_probe);
    form->addRow(tr("Bea&m"), m_beam);
    form->addRow(tr("&Operator"), m_operator);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(m_beamSummary);
    if (m_channel->count() == 0)
        layout->addWidget(wrappedLabel(tr("<b>This device sends no channel in ADC counts.</b> A gauge-factor "
                                          "calibration needs the raw bridge reading; connect the probe, or the "
                                          "simulator's gauge-factor calibration rig."),
                                       page));
    layout->addStretch();
    connect(m_probe, &QComboBox::currentIndexChanged, this, &GaugeFactorWizard::showBeam);
    connect(m_beam, &QComboBox::currentIndexChanged, this, &GaugeFactorWizard::showBeam);
    showBeam();
    return page;
}

CheckedPage* GaugeFactorWizard::createChainPage()
{
    auto* page = new CheckedPage([this] { return chain().has_value(); });
    page->setTitle(tr("Bridge, amplifier and ADC"));
    page->setSubTitle(tr("How the reading in counts is made: the fit needs it to turn counts into ΔR/R."));
    m_bridge = new QComboBox(page);
    m_bridge->setObjectName(QStringLiteral("bridgeBox"));
    m_bridge->addItem(tr("quarter bridge (one active gauge)"), static_cast<int>(BridgeType::Quarter));
    m_bridge->addItem(tr("half bridge, bending (two gauges, ±ε)"), static_cast<int>(BridgeType::HalfBending));
    m_bridge->addItem(tr("full bridge, bending (four gauges)"), static_cast<int>(BridgeType::FullBending));
    m_excitation = new QuantityEdit({1.0, tr("V"), tr("Excitation")}, 0.0, 50.0, page);
    m_gain = new QuantityEdit({1.0, {}, tr("Gain")}, 0.0, 1e6, page);
    m_bits = new QSpinBox(page);
    m_bits->setRange(8, 32);
    m_bits->setSuffix(tr(" bits"));
    m_reference = new QuantityEdit({1.0, tr("V"), tr("Reference")}, 0.0, 100.0, page);
    m_bipolar = new QCheckBox(tr("bipolar (±reference)"), page);
    m_nominal = new QuantityEdit({1.0, {}, tr("Gauge factor")}, 0.0, 1000.0, page);
    m_nominal->setObjectName(QStringLiteral("nominalGaugeFactor"));
    m_prefill = wrappedLabel({}, page);
    auto* form = new QFormLayout;
    form->addRow(tr("Bridge &type"), m_bridge);
    form->addRow(tr("E&xcitation"), m_excitation);
    form->addRow(tr("Amplifier &gain"), m_gain);
    form->addRow(tr("ADC &resolution"), m_bits);
    form->addRow(tr("ADC r&eference"), m_reference);
    form->addRow(QString(), m_bipolar);
    form->addRow(tr("Nominal gauge &factor (datasheet)"), m_nominal);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(m_prefill);
    layout->addStretch();
    for (QuantityEdit* edit : {m_excitation, m_gain, m_reference, m_nominal})
        connect(edit, &QuantityEdit::edited, page, &CheckedPage::recheck);
    return page;
}

CheckedPage* GaugeFactorWizard::createZeroPage()
{
    auto* page = new CheckedPage([this] { return m_zero.has_value(); });
    page->setTitle(tr("Zero"));
    page->setSubTitle(tr("Take every load off the beam and leave it still. The zero is taken as soon as the "
                         "signal is stable."));
    auto* indicator = new StabilityIndicator(m_watch, page);
    indicator->setUnit({1.0, tr("counts"), {}});
    m_criteria = new StabilityCriteria({1.0, tr("counts"), {}}, page);
    m_zeroText = new QLabel(tr("Zero: waiting for a stable signal…"), page);
    m_zeroText->setObjectName(QStringLiteral("zeroText"));
    auto* retakeZero = new QPushButton(tr("Re&take zero"), page);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(indicator);
    layout->addWidget(m_criteria);
    layout->addWidget(m_zeroText);
    layout->addWidget(retakeZero, 0, Qt::AlignLeft);
    layout->addStretch();
    connect(m_criteria, &StabilityCriteria::edited, this, &GaugeFactorWizard::applyStabilitySettings);
    connect(retakeZero, &QPushButton::clicked, this, &GaugeFactorWizard::takeZero);
    return page;
}

CheckedPage* GaugeFactorWizard::createLoadsPage()
{
    auto* page = new CheckedPage([this] { return m_result.has_value() && !m_pending; });
    page->setTitle(tr("Known loads"));
    page->setSubTitle(tr("Hang a known load on the tip, enter it and press Capture: the reading is the mean of the "
                         "first stable window after that. Several loads up to the working range."));
    m_panel = new CapturePanel(
        m_watch, {1.0, tr("counts"), {}},
        {{tr("g (mass on the tip)"), static_cast<int>(LoadUnit::Grams)},
         {tr("mgf (mass on the tip)"), static_cast<int>(LoadUnit::MilligramsForce)},
         {tr("mm (tip deflection)"), static_cast<int>(LoadUnit::TipDeflection_mm)}},
        {tr("Load"), tr("Force (mN)"), tr("Mean (counts)"), tr("σ (counts)"), tr("Residual (% FS)")}, page);
    m_panel->setLoad(20.0, static_cast<int>(LoadUnit::Grams));
    m_panel->setStatus(m_context.rig ? tr("Simulator: the rig hangs each load for you when you capture.") : QString());
    m_panel->plot()->setTitles(tr("Root strain ε (µε)"), tr("ΔR/R (10⁻⁶)"), tr("Residual (10⁻⁶)"));
    m_panel->plot()->setSeriesNames(tr("zero and loads"), {});
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_panel);
    connect(m_panel, &CapturePanel::captureRequested, this, &GaugeFactorWizard::capture);
    connect(m_panel, &CapturePanel::retakeRequested, this, &GaugeFactorWizard::retake);
    connect(m_panel, &CapturePanel::removeRequested, this, &GaugeFactorWizard::remove);
    return page;
}

CheckedPage* GaugeFactorWizard::createResultPage()
{
    auto* page = new CheckedPage([this] { return credible(); });
    page->setTitle(tr("Result"));
    page->setSubTitle(tr("Accept stores the calibration; the palpation view then reads this beam through it."));
    m_resultText = wrappedLabel({}, page);
    m_resultText->setObjectName(QStringLiteral("resultText"));
    m_resultText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_deviationWarning = wrappedLabel({}, page);
    m_deviationWarning->setObjectName(QStringLiteral("deviationWarning"));
    m_deviationWarning->setStyleSheet(QStringLiteral("color: #a15c00"));
    m_problems = wrappedLabel({}, page);
    m_problems->setObjectName(QStringLiteral("problemsText"));
    m_problems->setStyleSheet(QStringLiteral("color: #b00020"));
    m_warnPercent = new QDoubleSpinBox(page);
    m_warnPercent->setObjectName(QStringLiteral("warnPercent"));
    m_warnPercent->setRange(0.1, 100.0);
    m_warnPercent->setDecimals(1);
    m_warnPercent->setValue(5.0);
    m_warnPercent->setSuffix(tr(" %"));
    m_warnPercent->setMaximumWidth(120);
    m_limits = new FitLimitsBox({}, page);
    auto* warnForm = new QFormLayout;
    warnForm->addRow(tr("&Warn when the gauge factor differs from the nominal one by more than"), m_warnPercent);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_resultText);
    layout->addWidget(m_deviationWarning);
    layout->addWidget(m_problems);
    layout->addLayout(warnForm);
    layout->addWidget(m_limits);
    layout->addStretch();
    connect(m_warnPercent, &QDoubleSpinBox::valueChanged, this, &GaugeFactorWizard::showResult);
    connect(m_limits, &FitLimitsBox::changed, this, &GaugeFactorWizard::showResult);
    return page;
}

void GaugeFactorWizard::initializePage(int id)
{
    if (id == ChainPage) prefillChain();
    if (id == ZeroPage) {
        m_watch->setInput(m_context.buffer, m_channel->currentData().toULongLong());
        applyStabilityDefaults();
        takeZero();
    }
    if (id == LoadsPage) refit();
    if (id == ResultPage) showResult();
    QWizard::initializePage(id);
}

void GaugeFactorWizard::cleanupPage(int id)
{
    if (id == LoadsPage || id == ZeroPage) {
        m_watch->disarm();
        m_pending.reset();
    }
    QWizard::cleanupPage(id);
}

const core::sensors::CompliancePairProfile* GaugeFactorWizard::probe() const
{
    const int index = m_probe->currentIndex();
    if (index < 0 || index >= static_cast<int>(m_probes.size())) return nullptr;
    return &std::get<core::sensors::CompliancePairProfile>(*m_probes[static_cast<std::size_t>(index)].profile);
}

core::sensors::CantileverBeam GaugeFactorWizard::beam() const
{
    return core::sensors::CantileverBeam(m_beam->currentIndex() == 0 ? probe()->high : probe()->low);
}

std::string GaugeFactorWizard::sensorName() const
{
    return core::calibration::beamSensorName(probe()->name, m_beam->currentIndex() == 0);
}

void GaugeFactorWizard::showBeam()
{
    if (!probe()) {
        m_beamSummary->setText(tr("No compliance-probe profile can be read."));
        return;
    }
    const auto& g = m_beam->currentIndex() == 0 ? probe()->high : probe()->low;
    const auto b = beam();
    m_beamSummary->setText(tr("%1 × %2 × %3 mm, E = %4 GPa: k = %5 N/m, %6 µε per newton at the root.")
                               .arg(significant(g.length_m * 1e3), significant(g.width_m * 1e3),
                                    significant(g.thickness_m * 1e3), significant(g.youngsModulus_pa * 1e-9),
                                    significant(b.stiffness_n_per_m()), significant(b.rootStrainPerNewton() * 1e6)));
}

std::optional<core::straingauge::StrainGaugeChain> GaugeFactorWizard::chain() const
{
    const auto excitation = m_excitation->value(), gain = m_gain->value(), reference = m_reference->value(),
               nominal = m_nominal->value();
    if (!excitation || !gain || !reference || !nominal) return std::nullopt;
    core::straingauge::AdcSettings adc{m_bits->value(), *reference, m_bipolar->isChecked(), *gain};
    core::straingauge::BridgeSettings bridge{static_cast<BridgeType>(m_bridge->currentData().toInt()), *excitation,
                                             *nominal};
    try {
        return core::straingauge::StrainGaugeChain(adc, bridge);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

// The chain of this beam's newest calibration, else the settings the live
// palpation view reads counts with.
void GaugeFactorWizard::prefillChain()
{
    core::straingauge::AdcSettings adc;
    core::straingauge::BridgeSettings bridge;
    std::optional<core::storage::StoredCalibration> stored;
    QString unread;
    try {
        stored = core::storage::newestCalibrationIn(m_context.storePath.toStdString(),
                                                    core::calibration::kGaugeFactorKind, sensorName());
    } catch (const core::storage::StorageError& e) {
        unread = QString::fromStdString(e.what());
        qWarning("calibrations not read: %s", e.what());
    }
    if (stored) {
        const auto& r = stored->record;
        bridge.type = bridgeOfGauges(r.value("bridge_active_gauges").value_or(2.0));
        bridge.excitation_v = r.value("excitation_v").value_or(bridge.excitation_v);
        bridge.gaugeFactor = r.value("nominal_gauge_factor").value_or(bridge.gaugeFactor);
        adc.gain = r.value("amplifier_gain").value_or(adc.gain);
        adc.bits = static_cast<int>(r.value("adc_bits").value_or(adc.bits));
        adc.reference_v = r.value("adc_reference_v").value_or(adc.reference_v);
        adc.bipolar = r.value("adc_bipolar").value_or(1.0) != 0.0;
        m_prefill->setText(tr("Prefilled from this beam's calibration of %1 by %2.")
                               .arg(QString::fromStdString(r.timestampUtc), QString::fromStdString(r.operatorName)));
    } else if (!unread.isEmpty()) {
        m_prefill->setText(tr("Prefilled with the palpation view's settings: the store's calibrations could not be "
                              "read (%1). Check them against the amplifier.")
                               .arg(unread));
    } else {
        m_prefill->setText(tr("Prefilled with the settings the palpation view reads counts with (this beam has no "
                              "calibration yet). Check them against the amplifier."));
    }
    m_bridge->setCurrentIndex(m_bridge->findData(static_cast<int>(bridge.type)));
    m_excitation->setValue(bridge.excitation_v);
    m_gain->setValue(adc.gain);
    m_bits->setValue(adc.bits);
    m_reference->setValue(adc.reference_v);
    m_bipolar->setChecked(adc.bipolar);
    m_nominal->setValue(bridge.gaugeFactor);
    static_cast<CheckedPage*>(page(ChainPage))->recheck();
}

// Limits scaled to the ADC: a drift of 0.02 % and a σ of 0.1 % of full
// scale, far above a bridge amplifier's noise, far below a swinging beam.
void GaugeFactorWizard::applyStabilityDefaults()
{
    const double fullScale = chain()->fullScaleCounts();
    m_criteria->setSettings({1.0, 2e-4 * fullScale, 1e-3 * fullScale});
    applyStabilitySettings();
}

void GaugeFactorWizard::applyStabilitySettings()
{
    m_watch->setSettings(m_criteria->settings());
    if (currentId() == ZeroPage && !m_zero) m_watch->arm();
}

void GaugeFactorWizard::takeZero()
{
    if (m_context.rig) m_context.rig->place(0.0);
    m_zero.reset();
    m_zeroText->setText(tr("Zero: waiting for a stable signal…"));
    static_cast<CheckedPage*>(page(ZeroPage))->recheck();
    m_watch->arm();
}

double GaugeFactorWizard::forceOf(double value, LoadUnit unit) const
{
    switch (unit) {
    case LoadUnit::Grams:
        return value * 1e-3 * kStandardGravity_m_per_s2;
    case LoadUnit::MilligramsForce:
        return value * 1e-6 * kStandardGravity_m_per_s2;
    case LoadUnit::TipDeflection_mm:
        return value * 1e-3 * beam().stiffness_n_per_m();
    }
    return 0.0;
}

core::calibration::CalibrationLoad GaugeFactorWizard::loadOf(const LoadPoint& point) const
{
    core::calibration::CalibrationLoad load;
    if (point.unit == LoadUnit::TipDeflection_mm)
        load.tipDeflection_m = point.value * 1e-3;
    else
        load.force_n = forceOf(point.value, point.unit);
    load.meanCounts = point.window.mean;
    return load;
}

QString GaugeFactorWizard::loadText(const LoadPoint& point) const
{
    switch (point.unit) {
    case LoadUnit::Grams:
        return tr("%1 g").arg(significant(point.value, 6));
    case LoadUnit::MilligramsForce:
        return tr("%1 mgf").arg(significant(point.value, 6));
    case LoadUnit::TipDeflection_mm:
        return tr("%1 mm tip deflection").arg(significant(point.value, 6));
    }
    return {};
}

void GaugeFactorWizard::capture()
{
    if (m_panel->loadValue() <= 0.0) {
        m_panel->setStatus(tr("Enter the load first: the zero is already taken."));
        return;
    }
    m_pending = LoadPoint{m_panel->loadValue(), static_cast<LoadUnit>(m_panel->loadUnit()), {}};
    if (m_context.rig) m_context.rig->place(forceOf(m_pending->value, m_pending->unit));
    m_panel->setStatus(tr("Waiting for a stable reading with %1 on the tip…").arg(loadText(*m_pending)));
    m_panel->setWaiting(true);
    static_cast<CheckedPage*>(page(LoadsPage))->recheck();
    m_watch->arm();
}

void GaugeFactorWizard::captured(const core::calibration::WindowStatistics& window)
{
    if (!m_pending) return;
    LoadPoint point = *m_pending;
    point.window = window;
    m_pending.reset();
    m_panel->setWaiting(false);
    // A clipped reading is not a reading: the ADC, not the beam, set it.
    if (std::abs(window.mean) > 0.95 * chain()->fullScaleCounts()) {
        m_panel->setStatus(tr("%1 drives the ADC to its limit (%2 counts): not kept. Use a smaller load or "
                              "a lower gain.")
                               .arg(loadText(point), significant(window.mean, 6)));
    } else {
        if (m_retakeIndex && *m_retakeIndex < m_points.size())
            m_points[*m_retakeIndex] = point;
        else
            m_points.push_back(point);
        m_panel->setStatus(tr("Captured %1: %2 ± %3 counts.")
                               .arg(loadText(point), significant(window.mean, 6), significant(window.sigma, 3)));
    }
    m_retakeIndex.reset();
    refit();
    m_panel->focusEntry();
}

void GaugeFactorWizard::retake(int row)
{
    const LoadPoint& point = m_points.at(static_cast<std::size_t>(row));
    m_panel->setLoad(point.value, static_cast<int>(point.unit));
    m_retakeIndex = static_cast<std::size_t>(row);
    capture();
}

void GaugeFactorWizard::remove(int row)
{
    m_points.erase(m_points.begin() + row);
    refit();
}

// The fitted points are the zero (0) and the loads (1…).
QString GaugeFactorWizard::pointName(std::size_t fitted) const
{
    if (fitted == 0) return tr("The zero");
    return tr("Load %1 (%2)").arg(fitted).arg(loadText(m_points[fitted - 1]));
}

void GaugeFactorWizard::refit()
{
    m_result.reset();
    if (m_zero && m_points.size() >= 2) {
        std::vector<core::calibration::CalibrationLoad> loads;
        for (const LoadPoint& point : m_points) loads.push_back(loadOf(point));
        try {
            m_result = core::calibration::calibrateGaugeFactor(beam(), *chain(), m_zero->mean, loads, sensorName(),
                                                               m_operator->text().trimmed().toStdString());
        } catch (const std::invalid_argument& e) {
            m_panel->setFitSummary(tr("No fit: %1").arg(QString::fromStdString(e.what())));
        }
    }

    const double fullScale =
        m_result ? *std::max_element(m_result->relativeChange.begin(), m_result->relativeChange.end()) -
                       *std::min_element(m_result->relativeChange.begin(), m_result->relativeChange.end())
                 : 0.0;
    std::vector<QStringList> rows;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        const LoadPoint& p = m_points[i];
        const bool fitted = m_result && fullScale > 0.0;
        rows.push_back({loadText(p), significant(forceOf(p.value, p.unit) * 1e3, 5),
                        QLocale().toString(p.window.mean, 'f', 1), significant(p.window.sigma, 3),
                        fitted ? QLocale().toString(100.0 * m_result->strainFit.residuals[i + 1] / fullScale, 'f', 3)
                               : QStringLiteral("–")});
    }
    m_panel->setRows(rows, 1);

    std::vector<CalibrationPoint> points;
    if (m_result) {
        for (std::size_t i = 0; i < m_result->strain.size(); ++i)
            points.push_back({m_result->strain[i] * 1e6, m_result->relativeChange[i] * 1e6, true});
        const auto& fit = m_result->strainFit;
        m_panel->plot()->setData(points, std::make_pair(fit.slope, fit.intercept * 1e6));
        m_panel->setFitSummary(tr("Gauge factor %1 ± %2 (nominal %3), R² = %4, %5 points with the zero.")
                                   .arg(significant(fit.slope, 5), significant(fit.slopeStandardError, 2),
                                        significant(m_result->nominalGaugeFactor, 4),
                                        QLocale().toString(fit.rSquared, 'f', 6))
                                   .arg(fit.points));
    } else {
        m_panel->plot()->setData(points, std::nullopt);
        if (m_points.size() < 2) m_panel->setFitSummary(tr("Two loads are needed for a line."));
    }
    static_cast<CheckedPage*>(page(LoadsPage))->recheck();
}

bool GaugeFactorWizard::credible() const
{
    if (!m_result) return false;
    return core::calibration::judgeFit(m_result->strain, m_result->relativeChange, m_limits->limits()).credible();
}

void GaugeFactorWizard::showResult()
{
    if (!m_result) return;
    const QLocale locale;
    const auto& r = *m_result;
    const auto& fit = r.strainFit;
    m_resultText->setText(
        tr("<b>%1</b><br>Effective gauge factor <b>%2 ± %3</b> (standard error); nominal %4, a difference of "
           "%5 %.<br>Direct force calibration: %6 counts per newton over a zero of %7 counts (σ %8).<br>R² = %9, "
           "residual σ %10 × 10⁻⁶ ΔR/R, %11 points with the zero.")
            .arg(QString::fromStdString(sensorName()).toHtmlEscaped(), significant(r.gaugeFactor, 5),
                 significant(fit.slopeStandardError, 2), significant(r.nominalGaugeFactor, 4),
                 locale.toString(100.0 * r.deviationFromNominal, 'f', 2), significant(r.countsPerNewton, 6),
                 significant(r.zeroCounts, 6), significant(m_zero->sigma, 3), locale.toString(fit.rSquared, 'f', 6))
            .arg(significant(fit.residualStandardDeviation * 1e6, 3))
            .arg(fit.points));
    const bool warn = std::abs(r.deviationFromNominal) * 100.0 > m_warnPercent->value();
    m_deviationWarning->setText(
        warn ? tr("⚠ The gauge factor differs from the datasheet's by more than %1 %: check the bridge, gain and "
                  "excitation settings and the masses before you trust it (a poorly bonded gauge reads low).")
                   .arg(locale.toString(m_warnPercent->value(), 'f', 1))
             : QString());
    const auto limits = m_limits->limits();
    const QStringList problems = FitLimitsBox::problems(core::calibration::judgeFit(r.strain, r.relativeChange, limits),
                                                        limits, [this](std::size_t i) { return pointName(i); });
    m_problems->setText(problems.isEmpty() ? QString()
                                           : tr("Cannot be stored: %1").arg(problems.join(QLatin1Char(' '))));
    static_cast<CheckedPage*>(page(ResultPage))->recheck();
}

void GaugeFactorWizard::accept()
{
    if (!credible()) return;
    core::calibration::CalibrationRecord record = m_result->record;
    const core::straingauge::StrainGaugeChain c = *chain();
    record.operatorName = m_operator->text().trimmed().toStdString();
    record.timestampUtc = core::calibration::utcTimestampNow();
    const std::vector<std::pair<std::string, double>> setup{
        {"gauge_factor_standard_error", m_result->strainFit.slopeStandardError},
        {"zero_sigma_counts", m_zero->sigma},
        {"bridge_active_gauges", activeGauges(c.bridge().type)},
        {"excitation_v", c.bridge().excitation_v},
        {"amplifier_gain", c.adc().gain},
        {"adc_bits", static_cast<double>(c.adc().bits)},
        {"adc_reference_v", c.adc().reference_v},
        {"adc_bipolar", c.adc().bipolar ? 1.0 : 0.0}};
    record.values.insert(record.values.end(), setup.begin(), setup.end());
    const auto id = storeCalibrationOrSay(this, m_context.storePath, record);
    if (!id) return;
    m_watch->disarm();
    emit calibrationStored(*id, QString::fromStdString(record.sensorName));
    QWizard::accept();
}

}  // namespace tactiscope::ui
