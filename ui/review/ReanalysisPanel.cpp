// ReanalysisPanel: detector parameters, the worker run, saving the result.
#include "ui/review/ReanalysisPanel.h"

#include "core/storage/OpenSessionSource.h"

#include "ui/common/NumberText.h"
#include "ui/review/AnalysisName.h"

#include "core/ModeCapability.h"
#include "core/derived/StoredDetection.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/DefectRecords.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QShortcut>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace tactiscope::ui {
namespace {

QDoubleSpinBox* spin(QWidget* parent, const char* name, double minimum, double maximum, double value, int decimals,
                     const QString& suffix)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(minimum, maximum);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    return box;
}

QHBoxLayout* row(std::initializer_list<QWidget*> widgets)
{
    auto* layout = new QHBoxLayout;
    for (QWidget* w : widgets) layout->addWidget(w);
    layout->addStretch(1);
    return layout;
}

QString samplesText(std::size_t samples)
{
    return countText(static_cast<long long>(samples), QObject::tr("sample"), QObject::tr("samples"));
}

}  // namespace

ReanalysisPanel::ReanalysisPanel(const ReviewAccountContext& context, QWidget* parent)
    : ReviewAccount(tr("Re-analysis: surface-deflection detector (seed 000)"), parent),
      m_storePath(context.storePath),
      m_store(context.store),
      m_session(context.session),
      m_lagStart(spin(this, "lagStartSpin", 0.1, 10000.0, 2.0, 1, tr(" ms"))),
      m_lagStop(spin(this, "lagStopSpin", 0.1, 10000.0, 150.0, 1, tr(" ms"))),
      m_lagStep(spin(this, "lagStepSpin", 0.1, 1000.0, 2.0, 1, tr(" ms"))),
      m_lambdaRule(new QComboBox(this)),
      m_lambda(spin(this, "lambdaSpin", 0.1, 100000.0, 100.0, 1, tr(" ms"))),
      m_epsilon(spin(this, "epsilonSpin", 0.0, 1000.0, 7.0, 3, tr(" µε"))),
      m_threshold(spin(this, "thresholdSpin", 0.01, 0.999, 0.85, 3, {})),
      m_faceToFace(new QCheckBox(tr("Gauges face to face (negate b)"), this)),
      m_hold(spin(this, "holdSpin", 0.0, 10000.0, 20.0, 1, tr(" ms"))),
      m_spacing(spin(this, "spacingSpin", 0.0, 1000.0, core::detector::kPrototypeSpacing_m * 1e3, 2, tr(" mm"))),
      m_run(new QPushButton(tr("&Run"), this)),
      m_save(new QPushButton(tr("&Save as analysis…"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)),
      m_progress(new QProgressBar(this)),
      m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("reanalysisPanel"));
    m_lambdaRule->setObjectName(QStringLiteral("lambdaRule"));
    m_faceToFace->setObjectName(QStringLiteral("faceToFaceCheck"));
    m_run->setObjectName(QStringLiteral("runButton"));
    m_save->setObjectName(QStringLiteral("saveAnalysisButton"));
    m_status->setObjectName(QStringLiteral("analysisStatus"));
    m_cancel->setObjectName(QStringLiteral("cancelAnalysisButton"));
    m_progress->setObjectName(QStringLiteral("analysisProgress"));
    // Only while a run goes: how far through the samples, and a way out.
    m_cancel->setToolTip(tr("Stop this run; the events shown before stay"));
    m_cancel->hide();
    m_progress->hide();
    m_progress->setRange(0, 1000);
    m_status->setWordWrap(true);
    m_lambdaRule->addItems({tr("λ = lag (paper)"), tr("fixed λ")});
    m_lambda->setEnabled(false);
    m_spacing->setSpecialValueText(tr("not set"));
    m_lagStart->setToolTip(tr("Shortest lag c between the cantilevers' signals"));
    m_lagStop->setToolTip(tr("Longest lag c: the slowest scan the detector follows"));
    m_epsilon->setToolTip(tr("Regularisation ε, in strain (eq. 9)"));
    m_threshold->setToolTip(tr("Decision threshold on the partial correlation R"));
    m_hold->setToolTip(tr("Gaps in the decision up to this long are bridged within one event"));
    m_spacing->setToolTip(tr("Cantilever spacing, to give each event's scan speed and so its place along the "
                             "stroke (the paper's prototype: 15 mm)"));
    m_run->setToolTip(tr("Run the detector on the stored samples (Ctrl+Return)"));
    // A login that may not save analyses is told so before it tries.
    const QString cannotSave = QString::fromStdString(m_store.rights().noAnalyses);
    m_save->setToolTip(cannotSave.isEmpty() ? tr("Store these events under a name, beside the recorded ones")
                                            : tr("Not here: %1").arg(cannotSave));
    m_saveAllowed = cannotSave.isEmpty();
    m_save->setEnabled(false);

    // The live detector's lags: the paper's 2 ms steps, or the sample
    // interval when the probe streams slower.
    const double step_ms = std::max(2.0, 1e3 / std::max(m_session.sampleRate_hz, 1e-9));
    m_lagStart->setValue(step_ms);
    m_lagStep->setValue(step_ms);

    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    form->addRow(tr("Lags c"),
                 row({m_lagStart, new QLabel(tr("to"), this), m_lagStop, new QLabel(tr("step"), this), m_lagStep}));
    form->addRow(tr("Forgetting time"), row({m_lambdaRule, m_lambda}));
    form->addRow(tr("Regularisation ε"), m_epsilon);
    form->addRow(tr("Threshold on R"), m_threshold);
    form->addRow(QString(), m_faceToFace);
    form->addRow(tr("Hold"), m_hold);
    form->addRow(tr("Spacing"), m_spacing);
    form->addRow(row({m_run, m_save}));
    auto* running = new QHBoxLayout;
    running->addWidget(m_progress, 1);
    running->addWidget(m_cancel);
    form->addRow(running);
    form->addRow(m_status);
    setLayout(form);

    // The cantilevers by the roles they were recorded with, as the live detector read them.
    std::vector<core::ChannelDescriptor> descriptors;
    for (const auto& channel : m_store.channels(m_session.id)) descriptors.push_back(channel.descriptor);
    if (const auto cantilevers = core::modeChannels(m_session.metadata.mode, descriptors)) m_cantilevers = *cantilevers;
    // Through the session's filters when its mode read them so live.
    std::vector<std::string> names;
    for (const std::size_t c : m_cantilevers) names.push_back(descriptors[c].name);
    try {
        m_filters =
            core::signal::analysisFilters(core::signal::signalSetupFromJson(m_session.metadata.signalSetup), names);
    } catch (const std::invalid_argument&) {  // a setup this build cannot read: the samples as stored
        m_filters.reset();
    }
    if (m_cantilevers.size() < 2) {
        m_status->setText(tr("This session has no two cantilevers (A and B) among its channels: the detector needs "
                             "both."));
        m_run->setEnabled(false);
    } else {
        m_status->setText(tr("Change the parameters and run: the new events appear beside the recorded ones.") +
                          (m_filters ? tr(" The cantilevers are read through the session's filters, as its mode "
                                          "read them live (%1).")
                                           .arg(QString::fromStdString(m_filters->text))
                                     : QString()));
    }

    connect(m_lambdaRule, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_lambda->setEnabled(index == 1); });
    for (QDoubleSpinBox* box : {m_lagStart, m_lagStop, m_lagStep, m_lambda, m_epsilon, m_threshold, m_hold, m_spacing})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ReanalysisPanel::parametersChanged);
    connect(m_lambdaRule, &QComboBox::currentIndexChanged, this, &ReanalysisPanel::parametersChanged);
    connect(m_faceToFace, &QCheckBox::toggled, this, &ReanalysisPanel::parametersChanged);
    connect(m_run, &QPushButton::clicked, this, &ReanalysisPanel::run);
    connect(m_save, &QPushButton::clicked, this, &ReanalysisPanel::askNameAndSave);
    connect(m_cancel, &QPushButton::clicked, this, &ReanalysisPanel::cancel);
    connect(new QShortcut(runKeys(), this), &QShortcut::activated, this, &ReanalysisPanel::run);
}

ReanalysisPanel::~ReanalysisPanel() = default;

QKeySequence ReanalysisPanel::runKeys()
{
    return QKeySequence(tr("Ctrl+Return"));
}

std::optional<ReviewAccount::Unsaved> ReanalysisPanel::unsaved() const
{
    return Unsaved{core::storage::defectRecords(unsavedEvents(), core::storage::kLiveAnalysis), {}};
}

std::optional<core::detector::StretchSettings> ReanalysisPanel::settings()
{
    core::detector::StretchSettings s;
    s.parameters.sampleInterval_s = 1.0 / m_session.sampleRate_hz;
    try {
        s.parameters.lags_s = core::detector::lagRange_s(m_lagStart->value() * 1e-3, m_lagStop->value() * 1e-3,
                                                         m_lagStep->value() * 1e-3);
        if (m_lambdaRule->currentIndex() == 1) {
            s.parameters.lambdaRule = core::detector::LambdaRule::Fixed;
            s.parameters.fixedLambda_s = m_lambda->value() * 1e-3;
        }
        s.parameters.epsilon = m_epsilon->value() * 1e-6;
        s.parameters.threshold = m_threshold->value();
        s.parameters.faceToFace = m_faceToFace->isChecked();
        core::detector::resolve(s.parameters);  // checks them
    } catch (const std::invalid_argument& e) {
        m_status->setText(tr("These parameters cannot run: %1").arg(QString::fromStdString(e.what())));
        return std::nullopt;
    }
    s.hold_s = m_hold->value() * 1e-3;
    if (m_spacing->value() > 0.0) s.spacing_m = m_spacing->value() * 1e-3;
    s.threads = std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
    if (m_filters) {
        s.filters = m_filters->filters;
        s.filterStartStates = m_filters->startStates;
    }
    return s;
}

bool ReanalysisPanel::run()
{
    if (m_running || m_cantilevers.size() < 2) return false;
    const auto chosen = settings();
    if (!chosen) return false;
    m_running = true;
    m_run->setEnabled(false);
    m_save->setEnabled(false);
    m_progress->setValue(0);
    m_progress->show();
    m_cancel->show();
    m_status->setText(tr("Analysing %1 per channel…").arg(samplesText(m_session.sampleCount)));
    m_worker = std::jthread([this, path = m_storePath.toStdString(), id = m_session.id, cantilevers = m_cantilevers,
                             settings = *chosen](std::stop_token stop) {
        Outcome outcome;
        const auto started = std::chrono::steady_clock::now();
        try {
            const auto store = core::storage::openSessionSource(path, core::storage::Database::Access::ReadOnly);
            outcome.detection = core::derived::detectStoredSession(
                *store, id, cantilevers, settings, [this, &stop](std::uint64_t done, std::uint64_t total) {
                    QMetaObject::invokeMethod(
                        this, [this, done, total] { showProgress(done, total); }, Qt::QueuedConnection);
                    return !stop.stop_requested();
                });
        } catch (const std::exception& e) {
            outcome.error = QString::fromStdString(e.what());
        }
        outcome.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        QMetaObject::invokeMethod(
            this, [this, outcome = std::move(outcome)]() mutable { finish(std::move(outcome)); }, Qt::QueuedConnection);
    });
    return true;
}

void ReanalysisPanel::cancel()
{
    if (!m_running) return;
    m_worker.request_stop();
    m_cancel->setEnabled(false);
    m_status->setText(tr("Cancelling…"));
}

void ReanalysisPanel::showProgress(std::uint64_t done, std::uint64_t total)
{
    if (!m_running || total == 0) return;
    m_progress->setValue(static_cast<int>(1000 * done / total));
}

void ReanalysisPanel::finish(Outcome outcome)
{
    m_running = false;
    m_run->setEnabled(true);
    m_progress->hide();
    m_cancel->hide();
    m_cancel->setEnabled(true);
    if (!outcome.error.isEmpty()) {
        m_status->setText(tr("The re-analysis failed: %1").arg(outcome.error));
        return;
    }
    if (!outcome.detection) {
        m_status->setText(m_hasResult ? tr("Cancelled: the events shown are those of the previous run.")
                                      : tr("Cancelled before the end: no events are shown."));
        return;
    }
    m_events = std::move(outcome.detection->events);
    m_hasResult = true;
    m_saved = false;
    m_save->setEnabled(m_saveAllowed);
    m_status->setText(tr("%1 in %2, %3 s. Recorded events are unchanged until you save these as an analysis.")
                          .arg(countText(static_cast<long long>(m_events.size()), tr("event"), tr("events")),
                               samplesText(outcome.detection->analysedSamples), fixedText(outcome.elapsed_s, 2)));
    emit analysed();
    emit recordsChanged();
}

void ReanalysisPanel::parametersChanged()
{
    if (!m_hasResult || m_running) return;
    m_save->setEnabled(false);
    m_status->setText(tr("The parameters changed since the shown events: run again (Ctrl+Return) to see theirs."));
}

QString ReanalysisPanel::saveAs(const QString& name)
{
    const QString trimmed = name.trimmed();
    if (!m_hasResult || m_saved) return tr("Run the re-analysis first: this result is saved already.");
    try {
        if (const QString problem = analysisNameProblem(m_store, m_session.id, trimmed); !problem.isEmpty())
            return problem;
        m_store.addEvents(m_session.id, core::storage::defectRecords(m_events, trimmed.toStdString()));
    } catch (const core::storage::StorageError& e) {
        return tr("The analysis was not saved: %1").arg(QString::fromStdString(e.what()));
    }
    m_saved = true;
    m_save->setEnabled(false);
    m_status->setText(tr("Saved as the analysis \"%1\" (%2 events).").arg(trimmed).arg(m_events.size()));
    emit saved(trimmed);
    emit recordsChanged();
    return {};
}

void ReanalysisPanel::askNameAndSave()
{
    askAnalysisName(this, tr("the recorded events"), [this](const QString& name) {
        const QString error = saveAs(name);
        if (!error.isEmpty()) m_status->setText(error);
    });
}

}  // namespace tactiscope::ui
