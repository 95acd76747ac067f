// ReanalysisPanel: detector parameters, the worker run, saving the result.
#include "ui/review/ReanalysisPanel.h"

#include "ui/review/AnalysisName.h"

#include "core/storage/DefectRecords.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
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
    return samples >= 1000000 ? QObject::tr("%1 M").arg(static_cast<double>(samples) / 1e6, 0, 'f', 2)
                              : QString::number(samples);
}

}  // namespace

ReanalysisPanel::ReanalysisPanel(const QString& storePath, core::storage::SessionStore& store,
                                 const core::storage::SessionSummary& session, QWidget* parent)
    : QGroupBox(tr("Re-analysis: surface-deflection detector (seed 000)"), parent),
      m_storePath(storePath),
      m_store(store),
      m_session(session),
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
      m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("reanalysisPanel"));
    m_lambdaRule->setObjectName(QStringLiteral("lambdaRule"));
    m_faceToFace->setObjectName(QStringLiteral("faceToFaceCheck"));
    m_run->setObjectName(QStringLiteral("runButton"));
    m_save->setObjectName(QStringLiteral("saveAnalysisButton"));
    m_status->setObjectName(QStringLiteral("analysisStatus"));
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
    m_save->setToolTip(tr("Store these events under a name, beside the recorded ones"));
    m_save->setEnabled(false);

    // The live detector's lags: the paper's 2 ms steps, or the sample
    // interval when the probe streams slower.
    const double step_ms = std::max(2.0, 1e3 / std::max(session.sampleRate_hz, 1e-9));
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
    form->addRow(m_status);
    setLayout(form);

    const auto channels = store.channels(session.id);
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c].descriptor.kind == core::ChannelKind::Strain) m_cantilevers.push_back(c);
    if (m_cantilevers.size() < 2) {
        m_status->setText(tr("This session has fewer than two strain channels: the detector needs both cantilevers."));
        m_run->setEnabled(false);
    } else {
        m_status->setText(tr("Change the parameters and run: the new events appear beside the recorded ones."));
    }

    connect(m_lambdaRule, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_lambda->setEnabled(index == 1); });
    for (QDoubleSpinBox* box : {m_lagStart, m_lagStop, m_lagStep, m_lambda, m_epsilon, m_threshold, m_hold, m_spacing})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ReanalysisPanel::parametersChanged);
    connect(m_lambdaRule, &QComboBox::currentIndexChanged, this, &ReanalysisPanel::parametersChanged);
    connect(m_faceToFace, &QCheckBox::toggled, this, &ReanalysisPanel::parametersChanged);
    connect(m_run, &QPushButton::clicked, this, &ReanalysisPanel::run);
    connect(m_save, &QPushButton::clicked, this, &ReanalysisPanel::askNameAndSave);
    connect(new QShortcut(QKeySequence(tr("Ctrl+Return")), this), &QShortcut::activated, this, &ReanalysisPanel::run);
}

ReanalysisPanel::~ReanalysisPanel() = default;

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
    m_status->setText(tr("Analysing %1 samples per channel…").arg(samplesText(m_session.sampleCount)));
    m_worker = std::jthread([this, path = m_storePath.toStdString(), id = m_session.id, count = m_session.sampleCount,
                             cantilevers = m_cantilevers, settings = *chosen] {
        std::vector<core::detector::DefectEvent> events;
        std::size_t samples = 0;
        QString error;
        const auto started = std::chrono::steady_clock::now();
        try {
            core::storage::SessionStore store(path, core::storage::Database::Access::ReadOnly);
            std::vector<std::vector<double>> series;
            for (const std::size_t c : cantilevers) series.push_back(store.readChannel(id, c, 0, count));
            auto result = core::detector::detectStretches(series, settings);
            events = std::move(result.events);
            samples = result.analysedSamples;
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        QMetaObject::invokeMethod(
            this,
            [this, events = std::move(events), samples, elapsed_s, error]() mutable {
                finish(std::move(events), samples, elapsed_s, error);
            },
            Qt::QueuedConnection);
    });
    return true;
}

void ReanalysisPanel::finish(std::vector<core::detector::DefectEvent> events, std::size_t samples, double elapsed_s,
                             const QString& error)
{
    m_running = false;
    m_run->setEnabled(true);
    if (!error.isEmpty()) {
        m_status->setText(tr("The re-analysis failed: %1").arg(error));
        return;
    }
    m_events = std::move(events);
    m_hasResult = true;
    m_saved = false;
    m_save->setEnabled(true);
    m_status->setText(tr("%1 events in %2 samples, %3 s. Recorded events are unchanged until you save these as an "
                         "analysis.")
                          .arg(m_events.size())
                          .arg(samplesText(samples))
                          .arg(elapsed_s, 0, 'f', 2));
    emit analysed();
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
