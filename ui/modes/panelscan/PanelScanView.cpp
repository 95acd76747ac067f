// PanelScanView: parameter form → LiveDetectionSettings, events → table and alarm.
#include "ui/modes/panelscan/PanelScanView.h"

#include "ui/modes/ModeUi.h"

#include "devices/session/modes/PanelScanUnit.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/FixedColumns.h"
#include "ui/common/NumberText.h"
#include "ui/common/VocabularyText.h"
#include "ui/live/VerdictDialog.h"
#include "ui/plot/LivePlotWidget.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

constexpr int kAlarm_ms = 3000;  // how long a defect alarm stays up
// The lanes of the detector output: the decision, then both directions' best R.
constexpr std::size_t kBestRLane = 1;

QDoubleSpinBox* spinBox(double low, double high, double step, int decimals, const QString& suffix, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(low, high);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);  // act on the finished number, not each keystroke
    return box;
}

const QString kCalmAlarm = QStringLiteral("QLabel { background: palette(window); color: palette(mid); "
                                          "border: 1px solid palette(mid); border-radius: 6px; padding: 8px; }");
const QString kDefectAlarm = QStringLiteral("QLabel { background: #c62828; color: white; border-radius: 6px; "
                                            "padding: 8px; }");

}  // namespace

PanelScanView::PanelScanView(QWidget* parent)
    : LiveModeView(parent),
      m_lanes(new LivePlotWidget(this))
{
    m_threshold = spinBox(0.50, 0.999, 0.01, 3, QString(), this);
    m_lagFrom = spinBox(2, 1000, 2, 0, tr(" ms"), this);
    m_lagTo = spinBox(2, 2000, 2, 0, tr(" ms"), this);
    m_lagStep = spinBox(1, 100, 1, 0, tr(" ms"), this);
    m_epsilon = spinBox(0.0, 1000.0, 1.0, 1, tr(" µε"), this);
    m_lambdaRule = new QComboBox(this);
    m_lambdaRule->addItem(tr("λ = lag (paper)"));
    m_lambdaRule->addItem(tr("fixed λ"));
    m_lambda = spinBox(1, 10000, 10, 0, tr(" ms"), this);
    m_faceToFace = new QCheckBox(tr("gauges face to face"), this);
    m_spacing = spinBox(0, 1000, 1, 1, tr(" mm"), this);
    m_spacing->setSpecialValueText(tr("unknown"));
    m_sound = new QCheckBox(tr("sound on defect"), this);
    m_settingsError = new QLabel(this);
    m_settingsError->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_settingsError->setWordWrap(true);
    m_settingsError->hide();
    m_threshold->setObjectName(QStringLiteral("thresholdBox"));
    m_lagFrom->setObjectName(QStringLiteral("lagFromBox"));
    m_lagTo->setObjectName(QStringLiteral("lagToBox"));
    m_settingsError->setObjectName(QStringLiteral("settingsError"));

    auto* form = new QFormLayout;
    form->addRow(tr("Threshold on R"), m_threshold);
    // The lags' range and their step on two rows: on one, the detector's
    // box alone was wider than a laptop's window allows beside the lanes.
    auto* lags = new QHBoxLayout;
    lags->addWidget(m_lagFrom);
    lags->addWidget(new QLabel(tr("to"), this));
    lags->addWidget(m_lagTo);
    form->addRow(tr("Lags"), lags);
    form->addRow(tr("Lag step"), m_lagStep);
    form->addRow(tr("Regularisation ε"), m_epsilon);
    auto* lambda = new QHBoxLayout;
    lambda->addWidget(m_lambdaRule);
    lambda->addWidget(m_lambda);
    form->addRow(tr("Forgetting"), lambda);
    form->addRow(QString(), m_faceToFace);
    form->addRow(tr("Cantilever spacing"), m_spacing);
    form->addRow(QString(), m_sound);
    form->addRow(m_settingsError);
    auto* parameters = new QGroupBox(tr("Detector"), this);
    parameters->setLayout(form);

    m_alarm = new QLabel(this);
    m_alarm->setObjectName(QStringLiteral("alarmLabel"));
    QFont alarmFont = m_alarm->font();
    alarmFont.setPointSizeF(alarmFont.pointSizeF() * 1.5);
    alarmFont.setBold(true);
    m_alarm->setFont(alarmFont);
    m_alarm->setAlignment(Qt::AlignCenter);
    m_alarm->setMinimumHeight(56);
    m_countLabel = new QLabel(this);
    m_countLabel->setObjectName(QStringLiteral("defectCountLabel"));
    QFont countFont = m_countLabel->font();
    countFont.setPointSizeF(countFont.pointSizeF() * 1.2);
    m_countLabel->setFont(countFont);
    // The banner and the count change their text with every defect: their
    // widths must not move the column (and the lanes beside it), so they
    // take the width they are given and wrap within it.
    for (QLabel* label : {m_alarm, m_countLabel}) {
        label->setWordWrap(true);
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    }

    m_events = new QTableWidget(0, 5, this);
    m_events->setObjectName(QStringLiteral("defectTable"));
    m_events->setHorizontalHeaderLabels(
        {tr("Since connect (s)"), tr("Order"), tr("Peak R"), tr("Lag (ms)"), tr("mm/s")});
    m_events->verticalHeader()->hide();
    // Every cell on one line, whole: on a narrow screen the table scrolls
    // sideways rather than break "0.864" over two lines or cut a header.
    m_events->setWordWrap(false);
    fitColumns(*m_events, {QStringLiteral("0000.00"), tr("B then A"), QStringLiteral("0.000"), QStringLiteral("000"),
                           QStringLiteral("0000")});
    m_events->horizontalHeaderItem(4)->setToolTip(tr("Scan speed implied by the lag and the cantilever spacing"));
    m_events->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_events->setSelectionBehavior(QAbstractItemView::SelectRows);

    m_events->setMinimumHeight(90);
    auto* defects = new QVBoxLayout;
    defects->addWidget(m_alarm);
    defects->addWidget(m_countLabel);
    defects->addWidget(m_events, 1);

    // Lanes, the defects, the detector's settings side by side, so the mode
    // view stays low and the traces above keep most of the height. The list
    // and the settings keep their widths and the lanes take the rest: what
    // changes with every defect never moves the list (issue 37).
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 6, 0);
    m_lanes->setMinimumWidth(260);  // a lane narrower is a sliver of ticks
    layout->addWidget(m_lanes, 1);
    m_events->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);
    layout->addLayout(defects, 0);
    parameters->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    layout->addWidget(parameters, 0);

    for (QDoubleSpinBox* box : {m_threshold, m_lagFrom, m_lagTo, m_lagStep, m_epsilon, m_lambda, m_spacing})
        connect(box, &QDoubleSpinBox::valueChanged, this, &PanelScanView::applySettings);
    connect(m_lambdaRule, &QComboBox::currentIndexChanged, this, &PanelScanView::applySettings);
    connect(m_faceToFace, &QCheckBox::toggled, this, &PanelScanView::applySettings);
    m_alarmTimer.setSingleShot(true);
    connect(&m_alarmTimer, &QTimer::timeout, this, &PanelScanView::calmAlarm);
    calmAlarm();
    startPanel();
}

void PanelScanView::bind(const devices::session::LiveSession* session)
{
    const auto* unit = session ? session->unitAs<devices::session::PanelScanUnit>() : nullptr;
    m_detection = unit ? unit->detection() : nullptr;
    if (!m_detection) {
        m_lanes->clearSource();
        return;
    }
    // Short titles: the lanes are low, beside the defect list.
    // Named and levelled as the review and the report have it.
    const DisplayUnit decision =
        panelScanUi().laneUnit("decision").value_or(DisplayUnit{1.0, QString(), tr("Decision")});
    const DisplayUnit correlation{1.0, QString(), tr("Best R")};
    m_lanes->setSource(m_detection->output(), core::detector::LiveDetection::outputChannels(),
                       session->source().nominalSampleRate_hz(), {decision, correlation, correlation});
    showSettings(m_detection->settings());
    m_lanes->setThreshold(kBestRLane, m_detection->settings().parameters.threshold);
}

void PanelScanView::update(devices::session::LiveSession& session)
{
    const auto* unit = session.unitAs<devices::session::PanelScanUnit>();
    if (!unit) return;
    // In another mode the detector's marks leave the traces (a device of
    // two strain channels recorded in general mode showed "A then B").
    if (session.mode() != core::Mode::PanelScan) {
        if (m_traces && m_onTraces > 0) m_traces->clearEvents();
        m_onTraces = 0;
        m_tracesGeneration = ~std::uint64_t{0};  // back in this mode: marked afresh
        return;
    }
    if (unit->notJudged() != m_notJudged) {
        m_notJudged = unit->notJudged();
        showCount();
    }
    showDefects(*unit, session.lists());
    markOnTraces(unit->defects(), session.lists());
}

// The panel's defects where they happened on the traces (which count
// stream time); another generation of the lists is a new panel.
void PanelScanView::markOnTraces(const std::vector<core::detector::DefectEvent>& defects,
                                 const devices::session::LiveLists& lists)
{
    if (!m_traces) return;
    if (lists.generation != m_tracesGeneration) {
        m_tracesGeneration = lists.generation;
        m_traces->clearEvents();
        m_onTraces = 0;
    }
    for (; m_onTraces < defects.size(); ++m_onTraces)
        m_traces->addEvent(lists.origin_s + defects[m_onTraces].start_s, orderText(defects[m_onTraces].direction));
}

void PanelScanView::showSettings(const core::detector::LiveDetectionSettings& settings)
{
    m_showing = true;
    const auto& p = settings.parameters;
    m_threshold->setValue(p.threshold);
    m_lagFrom->setValue(p.lags_s.front() * 1e3);
    m_lagTo->setValue(p.lags_s.back() * 1e3);
    m_lagStep->setValue(p.lags_s.size() > 1 ? (p.lags_s[1] - p.lags_s[0]) * 1e3 : 2.0);
    m_epsilon->setValue(p.epsilon * 1e6);
    m_lambdaRule->setCurrentIndex(p.lambdaRule == core::detector::LambdaRule::EqualsLag ? 0 : 1);
    m_lambda->setValue(p.fixedLambda_s * 1e3);
    m_lambda->setEnabled(p.lambdaRule == core::detector::LambdaRule::Fixed);
    m_faceToFace->setChecked(p.faceToFace);
    m_spacing->setValue(settings.spacing_m ? *settings.spacing_m * 1e3 : 0.0);
    m_showing = false;
}

void PanelScanView::applySettings()
{
    if (m_showing || !m_detection) return;
    core::detector::LiveDetectionSettings settings = m_detection->settings();
    auto& p = settings.parameters;
    p.threshold = m_threshold->value();
    p.epsilon = m_epsilon->value() * 1e-6;
    p.lambdaRule =
        m_lambdaRule->currentIndex() == 0 ? core::detector::LambdaRule::EqualsLag : core::detector::LambdaRule::Fixed;
    p.fixedLambda_s = m_lambda->value() * 1e-3;
    p.faceToFace = m_faceToFace->isChecked();
    m_lambda->setEnabled(p.lambdaRule == core::detector::LambdaRule::Fixed);
    settings.spacing_m = m_spacing->value() > 0.0 ? std::optional(m_spacing->value() * 1e-3) : std::nullopt;
    try {
        p.lags_s =
            core::detector::lagRange_s(m_lagFrom->value() * 1e-3, m_lagTo->value() * 1e-3, m_lagStep->value() * 1e-3);
        m_detection->setSettings(settings);
        m_lanes->setThreshold(kBestRLane, p.threshold);
        m_settingsError->hide();
    } catch (const std::invalid_argument& e) {
        // The detector keeps its last good settings; say why these are not taken.
        m_settingsError->setText(tr("Not applied: %1").arg(QString::fromStdString(e.what())));
        m_settingsError->show();
    }
}

void PanelScanView::showDefects(const devices::session::PanelScanUnit& unit, const devices::session::LiveLists& lists)
{
    const auto& defects = unit.defects();
    const bool clockChanged = lists.clock != m_clock;
    m_clock = lists.clock;
    if (lists.generation != m_generation) {
        m_generation = lists.generation;
        startPanel();
    } else if (clockChanged) {
        showCount();
    }
    if (defects.size() == static_cast<std::size_t>(m_events->rowCount())) return;
    for (auto it = defects.begin() + m_events->rowCount(); it != defects.end(); ++it) {
        const auto& e = *it;
        const int row = m_events->rowCount();
        m_events->insertRow(row);
        const QStringList cells{fixedText(e.start_s, 2), orderText(e.direction), fixedText(e.peakR, 3),
                                fixedText(e.peakLag_s * 1e3, 0),
                                e.speed_m_per_s ? fixedText(*e.speed_m_per_s * 1e3, 0) : tr("—")};
        for (int c = 0; c < cells.size(); ++c) m_events->setItem(row, c, new QTableWidgetItem(cells[c]));
        raiseAlarm(e, e.start_s);
    }
    m_siteCount = unit.sites().sites.size();
    m_events->scrollToBottom();
    showCount();
}

void PanelScanView::showCount()
{
    const bool recorded = m_clock != devices::session::LiveClock::SinceConnect;
    m_events->horizontalHeaderItem(0)->setText(recorded ? tr("Recording (s)") : tr("Since connect (s)"));
    m_events->horizontalHeaderItem(0)->setToolTip(recorded ? tr("Seconds of the recording, as stored")
                                                           : tr("Seconds since the device connected: not recorded"));
    switch (m_clock) {
    case devices::session::LiveClock::Recording:
        m_countLabel->setText(defectCount() == 0 ? tr("No defect on this panel yet — %1").arg(verdictText())
                                                 : tr("%1 on this panel — %2").arg(countText(), verdictText()));
        break;
    case devices::session::LiveClock::Recorded:
        // The stored verdict's rule: a panel too short to judge has none.
        m_countLabel->setText(
            tr("%1 recorded on this panel — %2")
                .arg(countText(), m_notJudged.empty() ? verdictText() : QString::fromStdString(m_notJudged)));
        break;
    case devices::session::LiveClock::SinceConnect:
        m_countLabel->setText(tr("%1 since connect — not recorded").arg(countText()));
        break;
    }
}

void PanelScanView::raiseAlarm(const core::detector::DefectEvent& event, double shownTime_s)
{
    m_alarm->setText(tr("DEFECT  %1 at %2 s").arg(orderText(event.direction), fixedText(shownTime_s, 1)));
    m_alarm->setStyleSheet(kDefectAlarm);
    m_alarmTimer.start(kAlarm_ms);
    if (m_sound->isChecked()) QApplication::beep();
}

void PanelScanView::calmAlarm()
{
    m_alarm->setText(tr("No defect"));
    m_alarm->setStyleSheet(kCalmAlarm);
}

void PanelScanView::startPanel()
{
    m_events->setRowCount(0);
    m_siteCount = 0;
    showCount();
}

int PanelScanView::defectCount() const
{
    return m_events->rowCount();  // one row per defect of this panel
}

QString PanelScanView::countText() const
{
    // Each crossing of a dent is an event; the sites are the dents.
    return defectCount() == 0
               ? defectCountText(0)
               : tr("%1 at %2").arg(defectCountText(defectCount()), siteCountText(static_cast<int>(m_siteCount)));
}

QString PanelScanView::verdictText() const
{
    return wordText(core::automaticVerdict(m_siteCount));  // as the stored verdict counts
}

}  // namespace tactiscope::ui
