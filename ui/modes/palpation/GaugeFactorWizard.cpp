// GaugeFactorWizard: the beam and its chain around
// core::calibration::calibrateGaugeFactor.
#include "ui/modes/palpation/GaugeFactorWizard.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"

#include "core/storage/SessionStore.h"
#include "core/straingauge/ShuntCalibration.h"
#include "ui/calibration/CheckedPage.h"
#include "ui/calibration/WizardText.h"
#include "ui/common/QuantityEdit.h"

#include <algorithm>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace tactiscope::ui {
namespace {

using core::calibration::kStandardGravity_m_per_s2;
using core::straingauge::BridgeType;

// A bridge is stored as its number of active gauges
// (core::straingauge::activeGauges): a physical count rather than a code.
BridgeType bridgeOfGauges(double gauges)
{
    return gauges < 1.5 ? BridgeType::Quarter : gauges < 3.0 ? BridgeType::HalfBending : BridgeType::FullBending;
}

CalibrationWizard::Words gaugeWords()
{
    return {.zeroName = QObject::tr("Zero"),
            .signal = {1.0, QObject::tr("counts"), QObject::tr("Counts")},
            .signalDecimals = 1,
            .channelLabel = QObject::tr("&Channel (ADC counts)"),
            .channelFits = [](const core::ChannelDescriptor& c) { return c.unit == "count" || c.unit == "counts"; },
            .noChannel = QObject::tr("<b>This device sends no channel in ADC counts.</b> A gauge-factor calibration "
                                     "needs the raw bridge reading; connect the probe, or the simulator's gauge-factor "
                                     "calibration rig."),
            .mode = core::Mode::Palpation,
            .profileFits =
                [](const core::sensors::SensorProfile& p) {
                    return std::holds_alternative<core::sensors::CompliancePairProfile>(p);
                },
            .zeroSubTitle = QObject::tr("Take every load off the beam and leave it still. The zero is taken as soon as "
                                        "the signal is stable."),
            .loadsSubTitle = QObject::tr("Hang a known load on the tip, enter it and press Capture: once the signal is "
                                         "stable, the reading is the mean of a fresh stable window after that. Several "
                                         "loads up to the working range."),
            .loadUnits = {{QObject::tr("g (mass on the tip)"), 0},
                          {QObject::tr("mgf (mass on the tip)"), 1},
                          {QObject::tr("mm (tip deflection)"), 2}},
            .firstLoad = {20.0, 0},
            .plotX = {1e6, QObject::tr("µε"), QObject::tr("Root strain ε")},
            .plotY = {1e6, QObject::tr("10⁻⁶"), QObject::tr("ΔR/R")},
            .resultSubTitle =
                QObject::tr("Accept stores the calibration; the palpation view then reads this beam through it."),
            .limits = {}};
}

}  // namespace

GaugeFactorWizard::GaugeFactorWizard(CalibrationContext context, QWidget* parent)
    : CalibrationWizard(std::move(context), gaugeWords(), parent),
      m_beam(new QComboBox(this))
{
    static_assert(static_cast<int>(LoadUnit::TipDeflection_mm) == 2, "the load unit ids of gaugeWords()");
    setWindowTitle(tr("Gauge-factor calibration"));
    setObjectName(QStringLiteral("gaugeFactorWizard"));
    m_beam->setObjectName(QStringLiteral("beamBox"));
    m_beam->addItems({tr("stiff beam"), tr("soft beam")});
    // A rig that says which beam it holds (its channel's role) chooses it.
    const auto& channels = this->context().channels;
    if (std::ranges::any_of(channels, [](const auto& c) { return c.role == core::ChannelRole::SoftBeam; }) &&
        std::ranges::none_of(channels, [](const auto& c) { return c.role == core::ChannelRole::StiffBeam; }))
        m_beam->setCurrentIndex(1);
    addPages({{tr("Bea&m"), m_beam}}, createChainPage());
    addDeviationWarning();
    connect(profileBox(), &QComboBox::currentIndexChanged, this, &GaugeFactorWizard::showBeam);
    connect(m_beam, &QComboBox::currentIndexChanged, this, &GaugeFactorWizard::showBeam);
    showBeam();
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

// Under the result: how far the gauge factor may differ from the
// datasheet's before the wizard warns.
void GaugeFactorWizard::addDeviationWarning()
{
    QWidget* page = this->page(ResultPage);
    m_deviationWarning = wrappedLabel({}, page);
    m_deviationWarning->setObjectName(QStringLiteral("deviationWarning"));
    m_deviationWarning->setStyleSheet(QStringLiteral("color: #a15c00"));
    m_warnPercent = new QDoubleSpinBox(page);
    m_warnPercent->setObjectName(QStringLiteral("warnPercent"));
    m_warnPercent->setRange(0.1, 100.0);
    m_warnPercent->setDecimals(1);
    m_warnPercent->setValue(5.0);
    m_warnPercent->setSuffix(tr(" %"));
    m_warnPercent->setMaximumWidth(120);
    auto* warnForm = new QFormLayout;
    warnForm->addRow(tr("&Warn when the gauge factor differs from the nominal one by more than"), m_warnPercent);
    resultLayout()->insertWidget(1, m_deviationWarning);
    resultLayout()->insertLayout(3, warnForm);
    connect(m_warnPercent, &QDoubleSpinBox::valueChanged, this, &GaugeFactorWizard::resultShown);
}

void GaugeFactorWizard::initializePage(int id)
{
    if (id == SetupPage) prefillChain();
    CalibrationWizard::initializePage(id);
}

const core::sensors::CompliancePairProfile* GaugeFactorWizard::probe() const
{
    return chosenProfile<core::sensors::CompliancePairProfile>();
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
    if (!probe()) return;
    const auto& g = m_beam->currentIndex() == 0 ? probe()->high : probe()->low;
    const auto b = beam();
    setSensorSummary(tr("%1 × %2 × %3 mm, E = %4 GPa: k = %5 N/m, %6 µε per newton at the root.")
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

// The chain of this beam's newest calibration (a read-only look at the
// store), else the settings the live palpation view reads counts with.
void GaugeFactorWizard::prefillChain()
{
    core::straingauge::AdcSettings adc;
    core::straingauge::BridgeSettings bridge;
    std::optional<core::storage::StoredCalibration> stored;
    QString unread;
    try {
        stored = core::storage::newestCalibrationIn(context().store->path(), core::calibration::kGaugeFactorKind,
                                                    sensorName());
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
                               .arg(screenDateTime(r.timestampUtc), QString::fromStdString(r.operatorName)));
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
    recheck(SetupPage);
}

core::calibration::StabilitySettings GaugeFactorWizard::stabilityDefaults() const
{
    return core::calibration::gaugeStabilityDefaults(*chain());
}

std::optional<QString> GaugeFactorWizard::refusal(const Load& load) const
{
    if (!core::calibration::nearAdcLimit(load.window.mean, *chain())) return std::nullopt;
    return tr("%1 drives the ADC to its limit (%2 counts): not kept. Use a smaller load or a lower gain.")
        .arg(loadText(load), significant(load.window.mean, 6));
}

double GaugeFactorWizard::forceOf(const Load& load) const
{
    switch (static_cast<LoadUnit>(load.unit)) {
    case LoadUnit::Grams:
        return load.value * 1e-3 * kStandardGravity_m_per_s2;
    case LoadUnit::MilligramsForce:
        return load.value * 1e-6 * kStandardGravity_m_per_s2;
    case LoadUnit::TipDeflection_mm:
        return load.value * 1e-3 * beam().stiffness_n_per_m();
    }
    return 0.0;
}

QString GaugeFactorWizard::loadText(const Load& load) const
{
    switch (static_cast<LoadUnit>(load.unit)) {
    case LoadUnit::Grams:
        return tr("%1 g").arg(typedText(load.value));
    case LoadUnit::MilligramsForce:
        return tr("%1 mgf").arg(typedText(load.value));
    case LoadUnit::TipDeflection_mm:
        return tr("%1 mm tip deflection").arg(typedText(load.value));
    }
    return {};
}

CalibrationWizard::Fit GaugeFactorWizard::fitLoads()
{
    std::vector<core::calibration::CalibrationLoad> points;
    for (const Load& load : loads()) {
        core::calibration::CalibrationLoad point;
        if (static_cast<LoadUnit>(load.unit) == LoadUnit::TipDeflection_mm)
            point.tipDeflection_m = load.value * 1e-3;
        else
            point.force_n = forceOf(load);
        point.meanCounts = load.window.mean;
        point.meanStandardError_counts = load.window.meanStandardError;
        points.push_back(point);
    }
    m_result = core::calibration::calibrateGaugeFactor(beam(), *chain(), {zero()->mean, zero()->meanStandardError},
                                                       points, sensorName(), operatorName().toStdString());
    const auto& fit = m_result->strainFit;
    const auto [factor, error] = valueAndErrorTexts(m_result->gaugeFactor, m_result->gaugeFactorUncertainty);
    return {m_result->strain, m_result->relativeChange, fit,
            tr("Gauge factor %1 ± %2 (nominal %3), R² = %4, %5 points with the zero.")
                .arg(factor, error, compactText(m_result->nominalGaugeFactor, 4), fixedText(fit.rSquared, 6))
                .arg(fit.points)};
}

QString GaugeFactorWizard::resultHtml() const
{
    const auto& r = *m_result;
    const auto& fit = r.strainFit;
    const auto [factor, error] = valueAndErrorTexts(r.gaugeFactor, r.gaugeFactorUncertainty);
    // The ± is widened by the Birge ratio when the points scatter more than
    // their noise: say so, since it points at the loads, not the gauge.
    const QString scatter =
        fit.birgeRatio > 1.5
            ? tr("<br>The points scatter %1× as much as their noise allows (a load not settled, a swinging weight or "
                 "a wrong mass?): the ± is widened by that factor; retake the point farthest off the line.")
                  .arg(fixedText(fit.birgeRatio, 1))
            : QString();
    return tr("<b>%1</b><br>Effective gauge factor <b>%2 ± %3</b> (standard uncertainty, k = 1, from the readings' "
              "noise and the points' scatter); nominal %4, a difference of %5 %.<br>Direct force calibration: %6 "
              "counts per newton over a zero of %7 counts (σ %8).<br>R² = %9, residual σ %10 × 10⁻⁶ ΔR/R, %11 points "
              "with the zero.%12")
        .arg(QString::fromStdString(sensorName()).toHtmlEscaped(), factor, error, compactText(r.nominalGaugeFactor, 4),
             fixedText(100.0 * r.deviationFromNominal, 2),
             valueWithErrorText(r.countsPerNewton, r.forceFit.slopeStandardError),
             fixedText(r.zeroCounts, meanDecimals(*zero())), significant(zero()->sigma, 3), fixedText(fit.rSquared, 6))
        .arg(significant(fit.residualStandardDeviation * 1e6, 3))
        .arg(fit.points)
        .arg(scatter);
}

void GaugeFactorWizard::resultShown()
{
    if (!m_result) return;
    const bool warn = std::abs(m_result->deviationFromNominal) * 100.0 > m_warnPercent->value();
    m_deviationWarning->setText(
        warn ? tr("⚠ The gauge factor differs from the datasheet's by more than %1 %: check the bridge, gain and "
                  "excitation settings and the masses before you trust it (a poorly bonded gauge reads low).")
                   .arg(fixedText(m_warnPercent->value(), 1))
             : QString());
}

core::calibration::CalibrationRecord GaugeFactorWizard::record() const
{
    core::calibration::CalibrationRecord record = m_result->record;
    const core::straingauge::StrainGaugeChain c = *chain();
    const std::vector<std::pair<std::string, double>> setup{
        {"zero_sigma_counts", zero()->sigma},
        {"bridge_active_gauges", core::straingauge::activeGauges(c.bridge().type)},
        {"excitation_v", c.bridge().excitation_v},
        {"amplifier_gain", c.adc().gain},
        {"adc_bits", static_cast<double>(c.adc().bits)},
        {"adc_reference_v", c.adc().reference_v},
        {"adc_bipolar", c.adc().bipolar ? 1.0 : 0.0}};
    record.values.insert(record.values.end(), setup.begin(), setup.end());
    return record;
}

}  // namespace tactiscope::ui
