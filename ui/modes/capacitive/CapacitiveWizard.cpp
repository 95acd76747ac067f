// CapacitiveWizard: the beam's profile, the final zero and the sweep against
// a reference force around core::calibration::calibrateCapacitive.
#include "ui/modes/capacitive/CapacitiveWizard.h"
#include "ui/common/NumberText.h"

#include "core/UnitScale.h"
#include "core/calibration/CapacitiveSweep.h"
#include "core/sensors/CapacitiveBeam.h"
#include "core/sensors/SensorLimits.h"
#include "ui/calibration/CalibrationText.h"
#include "ui/calibration/CapturePanel.h"
#include "ui/calibration/CheckedPage.h"
#include "ui/calibration/WizardText.h"
#include "ui/modes/capacitive/ReferenceLink.h"
#include "ui/modes/capacitive/SweepCapture.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QTimer>
#include <QVBoxLayout>

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
                                     "the simulator's capacitive calibration rig. A board that prints its "
                                     "converter's counts is calibrated here once it prints picofarads "
                                     "(<tt>c[pF]:51.2</tt>)."),
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

// A channel that can be a reference force: a force in N, mN or µN.
bool referenceFits(const core::ChannelDescriptor& c)
{
    return (c.role == core::ChannelRole::ReferenceForce || c.kind == core::ChannelKind::Force) &&
           core::newtonsPer(c.unit).has_value();
}

QString turnsText(std::size_t turns)
{
    return turns == 1 ? QObject::tr("1 turn") : QObject::tr("%1 turns").arg(turns);
}

constexpr int kDeviceRole = Qt::UserRole + 1;  // the reference box's: its device's place in m_references

// A sweep is over once the reference has been back at rest this long: the
// beam's final baseline needs a stable window (2 s) after its creep.
constexpr double kAtRestToFinish_s = 5.0;

}  // namespace

CapacitiveWizard::CapacitiveWizard(CalibrationContext context, QWidget* parent)
    : CalibrationWizard(std::move(context), capacitiveWords(), parent)
{
    static_assert(static_cast<int>(Unit::Grams) == 1, "the load unit ids of capacitiveWords()");
    setWindowTitle(tr("Capacitive beam calibration (C0 and sensitivity)"));
    setObjectName(QStringLiteral("capacitiveWizard"));
    m_link = new ReferenceLink(this);
    m_sweepTimer = new QTimer(this);
    m_sweepTimer->setInterval(200);
    addPages({}, createMethodPage());
    m_finalZeroButton = new QPushButton(tr("&Final zero (all off)"));
    m_finalZeroButton->setObjectName(QStringLiteral("finalZeroButton"));
    m_finalZeroButton->setToolTip(tr("A second zero after the last weight is off: the drift between the two is taken "
                                     "out of every load."));
    panel()->addButton(m_finalZeroButton);
    m_startSweep = new QPushButton(tr("&Start sweep"));
    m_startSweep->setObjectName(QStringLiteral("startSweepButton"));
    m_startSweep->setToolTip(tr("Records the beam and the reference from now on: start with nothing on the beam."));
    panel()->addButton(m_startSweep);
    m_finishSweep = new QPushButton(tr("F&inish sweep"));
    m_finishSweep->setObjectName(QStringLiteral("finishSweepButton"));
    m_finishSweep->setToolTip(tr("Ends the recording and fits it (it ends by itself %1 s after the reference is back "
                                 "at rest).")
                                  .arg(kAtRestToFinish_s));
    panel()->addButton(m_finishSweep);
    connect(m_finalZeroButton, &QPushButton::clicked, this, &CapacitiveWizard::takeFinalZero);
    connect(m_startSweep, &QPushButton::clicked, this, &CapacitiveWizard::startSweep);
    connect(m_finishSweep, &QPushButton::clicked, this, &CapacitiveWizard::finishSweep);
    connect(m_sweepTimer, &QTimer::timeout, this, &CapacitiveWizard::pollSweep);
    connect(this, &QWizard::currentIdChanged, this, &CapacitiveWizard::showMethod);
    connect(profileBox(), &QComboBox::currentIndexChanged, this, &CapacitiveWizard::showBeam);
    showBeam();
}

CapacitiveWizard::~CapacitiveWizard() = default;

CheckedPage* CapacitiveWizard::createMethodPage()
{
    auto* page = new CheckedPage([this] { return !sweeping() || m_reference->count() > 0; });
    page->setTitle(tr("Loads"));
    page->setSubTitle(
        tr("Weights placed and removed by hand, or one continuous sweep read by a reference force: a "
           "load cell in series with the beam, on this device, on another in the session (Device ▸ Add to the "
           "session) or on one connected here."));
    auto* byWeights = new QRadioButton(tr("&Weights, placed and removed one at a time"), page);
    byWeights->setObjectName(QStringLiteral("byWeightsButton"));
    byWeights->setChecked(true);
    m_bySweep = new QRadioButton(tr("A &sweep against a reference force"), page);
    m_bySweep->setObjectName(QStringLiteral("bySweepButton"));
    auto* group = new QButtonGroup(page);
    group->addButton(byWeights);
    group->addButton(m_bySweep);
    m_reference = new QComboBox(page);
    m_reference->setObjectName(QStringLiteral("referenceBox"));
    m_referencePath = new QLineEdit(page);
    m_referencePath->setObjectName(QStringLiteral("referencePath"));
    m_referencePath->setPlaceholderText(tr("its port: /dev/ttyACM1, or an emulator's link"));
    auto* connectButton = new QPushButton(tr("Conn&ect"), page);
    connectButton->setObjectName(QStringLiteral("connectReferenceButton"));
    m_referenceStatus = wrappedLabel({}, page);
    m_referenceStatus->setObjectName(QStringLiteral("referenceStatus"));
    auto* other = new QHBoxLayout;
    other->addWidget(m_referencePath, 1);
    other->addWidget(connectButton);
    auto* sweepBox = new QWidget(page);
    auto* form = new QFormLayout(sweepBox);
    form->setContentsMargins(24, 0, 0, 0);
    form->addRow(tr("&Reference"), m_reference);
    auto* otherLabel = new QLabel(tr("Another &device"), page);
    otherLabel->setBuddy(m_referencePath);
    form->addRow(otherLabel, other);
    form->addRow(m_referenceStatus);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(byWeights);
    layout->addWidget(m_bySweep);
    layout->addWidget(sweepBox);
    layout->addWidget(wrappedLabel(tr("The sweep is paired with the beam at each sample's instant: on another device "
                                      "through the two clocks' mappings onto the computer's, whose uncertainty the "
                                      "result states. Loading and unloading are binned apart, as weights placed and "
                                      "removed are."),
                                   page));
    layout->addStretch();
    sweepBox->setEnabled(false);
    connect(m_bySweep, &QRadioButton::toggled, this, [this, sweepBox](bool on) {
        sweepBox->setEnabled(on);
        if (on) listReferences();  // devices may have joined the session since
        recheck(SetupPage);
    });
    connect(connectButton, &QPushButton::clicked, this, &CapacitiveWizard::connectReference);
    connect(m_referencePath, &QLineEdit::returnPressed, this, &CapacitiveWizard::connectReference);
    connect(m_link, &ReferenceLink::opened, this, [this] {
        listReferences();
        m_referenceStatus->setText(
            m_reference->findData(static_cast<qulonglong>(m_references.size() - 1), kDeviceRole) >= 0
                ? tr("Connected to %1.").arg(m_link->deviceName())
                : tr("%1 sends no force in N, mN or µN: it cannot be the reference.").arg(m_link->deviceName()));
    });
    connect(m_link, &ReferenceLink::failed, this, [this](const QString& why) {
        m_referenceStatus->setText(tr("Not connected: %1").arg(why));
        listReferences();
    });
    listReferences();
    return page;
}

bool CapacitiveWizard::sweeping() const
{
    return m_bySweep && m_bySweep->isChecked();
}

void CapacitiveWizard::listReferences()
{
    // This device, the session's others, the one connected for the wizard.
    m_references = {{tr("this device"), {}, context().channels, context().buffer, context().sampleRate_hz, {}}};
    if (context().sessionDevices)
        for (auto& other : context().sessionDevices()) {
            other.name = tr("%1, in the session").arg(other.name);
            m_references.push_back(std::move(other));
        }
    if (m_link->isOpen()) m_references.push_back(m_link->reference());
    m_reference->clear();
    for (std::size_t d = 0; d < m_references.size(); ++d)
        for (std::size_t c = 0; c < m_references[d].channels.size(); ++c)
            if (referenceFits(m_references[d].channels[c])) {
                m_reference->addItem(
                    tr("%1 (%2)").arg(QString::fromStdString(m_references[d].channels[c].name), m_references[d].name),
                    static_cast<qulonglong>(c));
                m_reference->setItemData(m_reference->count() - 1, static_cast<qulonglong>(d), kDeviceRole);
            }
    // The device connected for the sweep, else another device's force (a
    // reference on the calibrated device itself is the rare case).
    for (std::size_t d = m_references.size(); d-- > 1;)
        if (const int item = m_reference->findData(static_cast<qulonglong>(d), kDeviceRole); item >= 0) {
            m_reference->setCurrentIndex(item);
            break;
        }
    if (page(SetupPage)) recheck(SetupPage);  // (not while the page is being made)
}

std::size_t CapacitiveWizard::currentReferenceDevice() const
{
    return static_cast<std::size_t>(m_reference->currentData(kDeviceRole).toULongLong());
}

void CapacitiveWizard::connectReference()
{
    const QString path = m_referencePath->text().trimmed();
    if (path.isEmpty()) return;
    // A device of the session is read from there: its port is open
    // already, and opening it again would find it busy. (A port's source
    // is described as "PATH at BAUD baud", after its model when it said it.)
    listReferences();
    const QString described = path + QStringLiteral(" at ");
    for (std::size_t d = 1; d < m_references.size(); ++d) {
        const QString& source = m_references[d].source;
        if (!source.startsWith(described) && !source.contains(QLatin1Char('(') + described)) continue;
        const int item = m_reference->findData(static_cast<qulonglong>(d), kDeviceRole);
        if (item < 0) {
            m_referenceStatus->setText(
                tr("%1 sends no force in N, mN or µN: it cannot be the reference.").arg(m_references[d].name));
            return;
        }
        m_reference->setCurrentIndex(item);
        m_referenceStatus->setText(tr("%1 is in the session already: the reference is read from it.").arg(path));
        return;
    }
    m_referenceStatus->setText(tr("Connecting to %1…").arg(path));
    m_link->open(path);
}

// The Loads page captures weights by hand or records a sweep.
void CapacitiveWizard::showMethod(int page)
{
    if (page != LoadsPage) {
        m_sweepTimer->stop();
        m_capture.reset();
        return;
    }
    const bool sweep = sweeping();
    // Weights' loads and a sweep's points never mix: the other way's are
    // dropped when the way changed since.
    if (sweep != m_sweep.has_value() && !loads().empty()) setLoads({});
    if (!sweep) m_sweep.reset();
    currentPage()->setSubTitle(
        sweep ? tr("One sweep from nothing to full scale and back, read by the reference force. Its samples are "
                   "gathered in ten bins each way; each bin's capacitance at its middle force is a point.")
              : capacitiveWords().loadsSubTitle);
    panel()->setLoadsByHand(!sweep);
    m_finalZeroButton->setVisible(!sweep);
    m_startSweep->setVisible(sweep);
    m_finishSweep->setVisible(sweep);
    m_finishSweep->setEnabled(false);
    if (sweep)
        panel()->setStatus(tr("Press Start sweep with nothing on the beam, then push the load up to full scale and "
                              "back to nothing, at an even pace (a minute each way suits the soft silicone)."));
}

void CapacitiveWizard::startSweep()
{
    const auto channel = static_cast<std::size_t>(m_reference->currentData().toULongLong());
    const std::size_t device = currentReferenceDevice();
    if (m_reference->currentIndex() < 0 || device >= m_references.size() || !m_references[device].buffer ||
        channel >= m_references[device].channels.size()) {
        panel()->setStatus(tr("The reference device is gone: connect it again on the Loads page."));
        return;
    }
    const std::size_t beam = chosenChannel();
    m_capture = std::make_unique<SweepCapture>(
        SweepChannel{context().buffer, beam, core::faradsPer(context().channels[beam].unit).value_or(1.0)},
        SweepChannel{m_references[device].buffer, channel,
                     *core::newtonsPer(m_references[device].channels[channel].unit)});
    m_sweep.reset();
    setLoads({});
    m_startSweep->setEnabled(false);
    m_finishSweep->setEnabled(true);
    m_sweepTimer->start();
    panel()->setStatus(tr("Recording the sweep: now push the load up to full scale and back to nothing."));
}

void CapacitiveWizard::pollSweep()
{
    if (!m_capture) return;
    m_capture->poll();
    const auto now = m_capture->referenceNow_n(), peak = m_capture->referencePeak_n();
    if (!now) return;
    panel()->setStatus(tr("Recording the sweep: reference %1 mN, %2 mN at most so far; %3 samples of the beam.")
                           .arg(fixedText(*now * 1e3, 4), fixedText(*peak * 1e3, 4))
                           .arg(m_capture->beamSamples()));
    // Over once it rose by a few detection limits and rests again.
    if (m_capture->backAtRest(5.0 * kMilligramForce_n, 0.02 * *peak, kAtRestToFinish_s)) finishSweep();
}

void CapacitiveWizard::finishSweep()
{
    m_sweepTimer->stop();
    m_finishSweep->setEnabled(false);
    m_startSweep->setEnabled(true);
    if (!m_capture) return;
    m_capture->poll();
    const ReferenceDevice& reference = m_references.at(currentReferenceDevice());
    try {
        // This device's own reference shares its clock: none to pair by.
        const auto paired =
            m_capture->pair(context().hostClock ? context().hostClock() : std::nullopt,
                            reference.hostClock ? reference.hostClock() : std::nullopt, reference.sampleRate_hz);
        const auto steps =
            core::calibration::stepsFromSweep(paired.sweep.recording, {.stability = stabilityDefaults()});
        std::vector<Load> points;
        for (const auto& step : steps.steps.steps)
            points.push_back(
                {step.force_n / kMilligramForce_n, static_cast<int>(Unit::MilligramsForce), step.loading, step.window});
        m_sweep = Sweep{m_reference->currentText(),
                        steps.referenceZero_n,
                        steps.span_n,
                        steps.turns,
                        steps.lag_s,
                        paired.sweep.recording.t_s.size(),
                        paired.clockUncertainty_s,
                        paired.sweep.steepest_n_per_s,
                        steps.steps.input.finalBaseline};
        panel()->setStatus(tr("Sweep to %1 mN, %2, %3 samples paired: its points are below.")
                               .arg(fixedText(steps.span_n * 1e3, 4), turnsText(steps.turns))
                               .arg(paired.sweep.recording.t_s.size()));
        setLoads(std::move(points));
    } catch (const std::invalid_argument& e) {
        panel()->setStatus(tr("No sweep: %1.").arg(QString::fromStdString(e.what())));
    }
    m_capture.reset();
}

const core::sensors::CapacitiveBeamProfile* CapacitiveWizard::profile() const
{
    return chosenProfile<core::sensors::CapacitiveBeamProfile>();
}

void CapacitiveWizard::showBeam()
{
    if (!profile()) return;
    const core::sensors::CapacitiveBeam beam(profile()->geometry);
    QString summary =
        tr("The beam model expects C0 = %1 pF, %2 pF/mN and k = %3 N/m: the calibration measures the "
           "first two on the real beam.")
            .arg(significant(profile()->geometry.c0_f * 1e12), significant(beam.capacitancePerNewton_f_per_n() * 1e9),
                 significant(beam.stiffness_n_per_m()));
    // The live view watches the beam's limits while the wizard loads it: a
    // full-scale load past them raises its alarm, and that is said first.
    for (const auto& limit : core::sensors::profileLimits(core::sensors::SensorProfile{*profile()}, context().channels))
        if (limit.limit.quantity == "force" && limit.limit.warning && limit.limit.critical) {
            const auto mgf = [](double n) { return significant(n / kMilligramForce_n, 3); };
            summary += QLatin1Char(' ') +
                       tr("Its limits: warning above %1 mgf, critical above %2 mgf (%3). Heavier loads raise the "
                          "live view's alarms: expected while calibrating, and no session records them.")
                           .arg(mgf(limit.limit.warning->low), mgf(limit.limit.critical->low),
                                QString::fromStdString(limit.basis));
        }
    setSensorSummary(summary);
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
    if (m_sweep) return tr("%1 mgf").arg(significant(load.value, 4));  // a bin's middle, not a typed load
    return static_cast<Unit>(load.unit) == Unit::Grams ? tr("%1 g").arg(typedText(load.value))
                                                       : tr("%1 mgf").arg(typedText(load.value));
}

CalibrationWizard::Fit CapacitiveWizard::fitLoads()
{
    core::calibration::CapacitiveCalibrationInput input;
    input.baseline = *zero();
    input.finalBaseline = m_sweep ? m_sweep->finalBaseline : finalZero();
    input.stiffness_n_per_m = core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m();
    input.baselineWander_f_per_sqrt_s = profile()->baselineWander_f_per_sqrt_s;
    for (const Load& load : loads())
        input.steps.push_back({forceOf(load), std::nullopt, load.window.mean, load.window.middle_s(), load.loading,
                               load.window.meanStandardError});
    m_result = core::calibration::calibrateCapacitive(input, profile()->name, operatorName().toStdString());
    const auto& fit = *m_result->forceFit;
    const auto [sensitivity, error] = valueAndErrorTexts(fit.slope * 1e9, fit.slopeStandardError * 1e9);
    return {m_result->fitForce_n, m_result->fitDelta_f, fit,
            tr("Sensitivity %1 ± %2 pF/mN, R² = %3, %4 points with the zero.")
                .arg(sensitivity, error, fixedText(fit.rSquared, 6))
                .arg(fit.points)};
}

// What a sweep's points rest on: the reference, its zero, and how well its
// instants meet the beam's.
QString CapacitiveWizard::sweepHtml() const
{
    if (!m_sweep) return {};
    const Sweep& w = *m_sweep;
    QString timing;
    if (w.clockUncertainty_s && *w.clockUncertainty_s > 0.0)
        timing = tr(" The two devices' clocks agree within ±%1 ms (standard uncertainty): at most %2 µN on the "
                    "sweep's steepest part; an offset between them acts as a lag and goes out with the beam's.")
                     .arg(fixedText(*w.clockUncertainty_s * 1e3, 3),
                          significant(*w.clockUncertainty_s * w.steepest_n_per_s * 1e6, 2));
    return tr("<br>Against the reference force %1 (its zero, %2 µN, taken off): a sweep to %3 mN, %4, %5 samples "
              "of the beam paired with it. The beam settles behind the force with τ = %6 s (a first-order lag), "
              "taken out before the points were binned.")
               .arg(w.reference.toHtmlEscaped(), fixedText(w.zero_n * 1e6, 2), fixedText(w.span_n * 1e3, 4),
                    turnsText(w.turns))
               .arg(w.paired)
               .arg(fixedText(w.lag_s, 3)) +
           timing;
}

QString CapacitiveWizard::resultHtml() const
{
    const QLocale locale;
    const auto& r = *m_result;
    const auto& fit = *r.forceFit;
    const bool finalBaseline = m_sweep ? m_sweep->finalBaseline.has_value() : finalZero().has_value();
    const QString drift =
        finalBaseline ? tr("drift %1 pF/min (removed from every load)").arg(fixedText(r.drift_f_per_s * 1e12 * 60.0, 4))
                      : tr("no final zero, so no drift correction");
    const QString hysteresis =
        !r.hysteresis ? tr("not measured (no load was both placed and removed)")
        : r.hysteresisNoise
            ? tr("%1 % of full scale, an upper bound of the silicone's (the loads' noise alone reads up to %2 %)")
                  .arg(fixedText(*r.hysteresis * 100, 2), fixedText(*r.hysteresisNoise * 100, 2))
            : tr("%1 % of full scale").arg(fixedText(*r.hysteresis * 100, 2));
    const QString basis =
        !r.sensitivityUncertainty ? tr("from the points' scatter")
        : profile()->baselineWander_f_per_sqrt_s
            ? tr("from the loads' and zeros' noise and the beam's baseline stability, %1 pF/√s")
                  .arg(significant(*profile()->baselineWander_f_per_sqrt_s * 1e12, 3))
            : tr("from the loads' and zeros' noise; the baseline's wander between the zeros is not in it: the "
                 "profile states no baseline stability");
    const auto [sensitivity, error] = valueAndErrorTexts(fit.slope * 1e9, fit.slopeStandardError * 1e9);
    QString cautions;
    for (const std::string& caution : r.cautions)
        cautions += QStringLiteral("<br><span style=\"color:#b00020\">%1</span>")
                        .arg(tr("Caution: %1.").arg(QString::fromStdString(caution)).toHtmlEscaped());
    return tr("<b>%1</b><br>C0 = <b>%2 pF</b>, noise σ %3 pF; %4.<br>Sensitivity <b>%5 ± %6 pF/mN</b> (standard "
              "uncertainty, k = 1, %14), intercept %7 pF, R² = %8; relative sensitivity %9 "
              "per mN.<br>Hysteresis %10.<br>Detection limit (3σ): %11, a tip displacement of %12 through k = %13 "
              "N/m.")
               .arg(QString::fromStdString(profile()->name).toHtmlEscaped(), fixedText(r.c0_f * 1e12, 4),
                    fixedText(r.baselineSigma_f * 1e12, 4), drift, sensitivity, error,
                    fixedText(fit.intercept * 1e12, 4), fixedText(fit.rSquared, 6),
                    significant(*r.relativeSensitivity_per_n * 1e-3, 3))
               .arg(hysteresis, detectionLimitText(*r.detectionLimit_n),
                    siText(r.detectionLimit_m.value_or(0), QStringLiteral("m"), 3),
                    significant(core::sensors::CapacitiveBeam(profile()->geometry).stiffness_n_per_m(), 3))
               .arg(basis) +
           sweepHtml() + cautions;
}

core::calibration::CalibrationRecord CapacitiveWizard::record() const
{
    core::calibration::CalibrationRecord record = m_result->record;
    record.values.emplace_back("sensitivity_standard_error_pf_per_mn", m_result->forceFit->slopeStandardError * 1e9);
    if (m_sweep) {  // what the sweep's points rest on
        record.values.emplace_back("reference_zero_mn", m_sweep->zero_n * 1e3);
        record.values.emplace_back("sweep_span_mn", m_sweep->span_n * 1e3);
        record.values.emplace_back("beam_lag_s", m_sweep->lag_s);
        if (m_sweep->clockUncertainty_s) record.values.emplace_back("clock_u_ms", *m_sweep->clockUncertainty_s * 1e3);
    }
    return record;
}

}  // namespace tactiscope::ui
