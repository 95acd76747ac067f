// CalibrationHistory: sensors, records, drift plot, sessions per record.
#include "ui/calibration/CalibrationHistory.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"
#include "ui/common/VocabularyText.h"

#include "core/calibration/CalibrationDrift.h"
#include "core/storage/SessionStore.h"
#include "ui/calibration/WizardText.h"
#include "ui/common/ProblemReport.h"

#include <QDateTime>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QListWidget>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace tactiscope::ui {
namespace {

// Date ticks at local midnights, a few of them, each date once and in the
// locale's form: a date-time ticker's sub-day steps wrote the same date
// under several ticks.
QSharedPointer<QCPAxisTickerText> dayTicks(const QCPRange& range)
{
    QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
    const QDate first = QDateTime::fromSecsSinceEpoch(static_cast<qint64>(std::ceil(range.lower))).date().addDays(1);
    const QDate last = QDateTime::fromSecsSinceEpoch(static_cast<qint64>(std::floor(range.upper))).date();
    const qint64 step = std::max<qint64>(1, (first.daysTo(last) + 6) / 6);
    for (QDate day = first; day <= last; day = day.addDays(step))
        ticker->addTick(static_cast<double>(QDateTime(day, QTime(0, 0)).toSecsSinceEpoch()), screenDate(day));
    return ticker;
}

// The value a kind of calibration is about, its standard error and how it
// is named and shown.
struct MainValue {
    const char* key;
    const char* standardErrorKey;
    const char* title;
    const char* unit;  // its trend's, per year; none for a pure number
};

MainValue mainValueOf(const std::string& kind)
{
    if (kind == core::calibration::kCapacitiveKind)
        return {"sensitivity_pf_per_mn", "sensitivity_standard_error_pf_per_mn", "Sensitivity (pF/mN)", "pF/mN"};
    if (kind == core::calibration::kShuntCheckKind)
        return {"shunt_deviation_percent", "", "Shunt check deviation (%)", "%"};
    return {"gauge_factor", "gauge_factor_standard_error", "Gauge factor", ""};
}

// How far apart the oldest and newest records are: "19 min", "5 h", "40 days".
QString spanText(double seconds)
{
    if (seconds < 3600.0) return QObject::tr("%1 min").arg(std::round(seconds / 60.0));
    if (seconds < 2.0 * 86400.0) return QObject::tr("%1 h").arg(std::round(seconds / 3600.0));
    return QObject::tr("%1 days").arg(std::round(seconds / 86400.0));
}

double secondsOf(const std::string& timestampUtc)
{
    return static_cast<double>(storedTime(timestampUtc).toSecsSinceEpoch());
}

}  // namespace

CalibrationHistory::CalibrationHistory(const QString& storePath, QWidget* parent)
    : QDialog(parent),
      m_storePath(storePath),
      m_sensors(new QListWidget(this)),
      m_records(new QTableWidget(0, 7, this)),
      m_drift(wrappedLabel({}, this)),
      m_plot(new QCustomPlot(this)),
      m_sessions(new QListWidget(this)),
      m_problem(wrappedLabel({}, this))
{
    setWindowTitle(tr("Calibration history"));
    setObjectName(QStringLiteral("calibrationHistory"));
    m_sensors->setObjectName(QStringLiteral("sensorList"));
    // A beam's name ends in "— stiff beam" or "— soft beam": wrapped, never cut.
    m_sensors->setWordWrap(true);
    m_records->setObjectName(QStringLiteral("recordTable"));
    m_drift->setObjectName(QStringLiteral("driftText"));
    m_sessions->setObjectName(QStringLiteral("sessionList"));
    m_problem->setObjectName(QStringLiteral("problemText"));
    m_records->setHorizontalHeaderLabels(
        {tr("Date"), tr("Operator"), tr("Value"), tr("± SE"), tr("R²"), tr("Points"), tr("Sessions")});
    m_records->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_records->setSelectionMode(QAbstractItemView::SingleSelection);
    m_records->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_records->verticalHeader()->setVisible(false);
    m_records->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The summary's two lines are kept whether it says one or two: the plot
    // below stayed put no more when the sensor changed.
    m_drift->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_drift->setFixedHeight(2 * m_drift->fontMetrics().lineSpacing() + 4);
    m_plot->setMinimumHeight(200);
    m_plot->xAxis->setLabel(tr("Date of calibration"));
    QCPGraph* graph = m_plot->addGraph();
    graph->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.2));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 7));
    auto* errors = new QCPErrorBars(m_plot->xAxis, m_plot->yAxis);
    errors->setDataPlottable(graph);
    errors->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.0));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));

    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addWidget(m_records, 2);
    rightLayout->addWidget(m_drift);
    rightLayout->addWidget(m_plot, 2);
    rightLayout->addWidget(new QLabel(tr("Sessions recorded with the selected calibration:"), right));
    rightLayout->addWidget(m_sessions, 1);
    auto* splitter = new QSplitter(this);
    splitter->addWidget(m_sensors);
    splitter->addWidget(right);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({240, 760});
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_problem);
    layout->addWidget(splitter);
    resize(1000, 700);

    connect(m_sensors, &QListWidget::currentRowChanged, this, &CalibrationHistory::showSensor);
    connect(m_records, &QTableWidget::currentCellChanged, this, &CalibrationHistory::showSessions);
    reload();
}

void CalibrationHistory::reload()
{
    m_all.clear();
    m_problem->clear();
    if (QFileInfo::exists(m_storePath)) {
        try {
            core::storage::SessionStore store(m_storePath.toStdString(), core::storage::Database::Access::ReadOnly);
            m_all = store.calibrations();
        } catch (const core::storage::StorageError& e) {
            m_problem->setText(tr("The store cannot be read: %1").arg(QString::fromStdString(e.what())));
            logProblem({tr("Calibration history"), m_problem->text(), {}, {}});
        }
    }
    std::set<QString> sensors;
    for (const auto& stored : m_all) sensors.insert(QString::fromStdString(stored.record.sensorName));
    m_sensors->clear();
    for (const QString& sensor : sensors) m_sensors->addItem(sensor);
    if (m_all.empty() && m_problem->text().isEmpty())
        m_problem->setText(tr("No calibrations in %1 yet: the Tools menu has the calibration wizards.")
                               .arg(QDir::toNativeSeparators(m_storePath)));
    if (m_sensors->count() > 0) m_sensors->setCurrentRow(0);
}

bool CalibrationHistory::selectSensor(const QString& sensor)
{
    const auto found = m_sensors->findItems(sensor, Qt::MatchExactly);
    if (found.isEmpty()) return false;
    m_sensors->setCurrentItem(found.front());
    return true;
}

void CalibrationHistory::selectRecord(int row)
{
    m_records->selectRow(row);
}

std::vector<QPointF> CalibrationHistory::plottedPoints() const
{
    std::vector<QPointF> points;
    for (auto it = m_plot->graph(0)->data()->constBegin(); it != m_plot->graph(0)->data()->constEnd(); ++it)
        points.emplace_back(it->key, it->value);
    return points;
}

void CalibrationHistory::showSensor()
{
    m_shown.clear();
    const QString sensor = m_sensors->currentItem() ? m_sensors->currentItem()->text() : QString();
    for (const auto& stored : m_all)
        if (QString::fromStdString(stored.record.sensorName) == sensor) m_shown.push_back(&stored);
    std::stable_sort(m_shown.begin(), m_shown.end(),
                     [](const auto* a, const auto* b) { return a->record.timestampUtc < b->record.timestampUtc; });

    std::map<std::int64_t, std::size_t> sessionCounts;
    if (!m_shown.empty()) {
        try {
            core::storage::SessionStore store(m_storePath.toStdString(), core::storage::Database::Access::ReadOnly);
            for (const auto* stored : m_shown)
                sessionCounts[stored->id] = store.sessionsUsingCalibration(stored->id).size();
        } catch (const core::storage::StorageError&) {
            // counts stay unknown; the records are still worth showing
        }
    }

    m_records->setRowCount(static_cast<int>(m_shown.size()));
    // The values' column shares its decimals, those of the coarsest standard error.
    std::vector<double> standardErrors;
    for (const auto* stored : m_shown)
        if (const auto e = stored->record.value(mainValueOf(stored->record.kind).standardErrorKey))
            standardErrors.push_back(*e);
    const int decimals = sharedDecimals(standardErrors, 4);
    std::vector<double> t, v;
    QVector<double> keys, values, errors;
    QString title, unit;
    for (std::size_t i = 0; i < m_shown.size(); ++i) {
        const auto& r = m_shown[i]->record;
        const MainValue main = mainValueOf(r.kind);
        title = tr(main.title);
        unit = QString::fromUtf8(main.unit);
        const auto value = r.value(main.key);
        const auto error = r.value(main.standardErrorKey);
        const bool active = i + 1 == m_shown.size();
        // A check has no fit and is never "in use": it passed or failed.
        const bool check = r.kind == core::calibration::kShuntCheckKind;
        const QString state = check    ? (r.value("shunt_passed") == 1.0 ? tr("  ✓ passed") : tr("  ✗ failed"))
                              : active ? tr("  ✓ active")
                                       : QString();
        const QStringList cells{screenDateTime(r.timestampUtc) + state,
                                QString::fromStdString(r.operatorName),
                                value ? fixedText(*value, decimals) : QStringLiteral("–"),
                                error ? significant(*error, 2) : QStringLiteral("–"),
                                check ? QStringLiteral("–") : fixedText(r.fit.rSquared, 6),
                                check ? QStringLiteral("–") : QString::number(r.fit.points),
                                sessionCounts.count(m_shown[i]->id) ? QString::number(sessionCounts[m_shown[i]->id])
                                                                    : QStringLiteral("?")};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c >= 2) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_records->setItem(static_cast<int>(i), c, item);
        }
        if (!value) continue;
        t.push_back(secondsOf(r.timestampUtc));
        v.push_back(*value);
        keys.push_back(t.back());
        values.push_back(*value);
        errors.push_back(error.value_or(0.0));
    }
    m_plot->graph(0)->setData(keys, values, true);
    if (auto* bars = qobject_cast<QCPErrorBars*>(m_plot->plottable(1))) bars->setData(errors);
    m_plot->yAxis->setLabel(title);
    m_plot->rescaleAxes();
    // Some air either side (a day at least), the value axis opened a little, so a single
    // record or identical values still show as a point.
    const QCPRange x = m_plot->xAxis->range();
    const double xPad = std::max(0.06 * x.size(), 86400.0);
    m_plot->xAxis->setRange(x.lower - xPad, x.upper + xPad);
    m_plot->xAxis->setTicker(dayTicks(m_plot->xAxis->range()));
    const QCPRange y = m_plot->yAxis->range();
    const double pad = std::max(0.1 * y.size(), 1e-3 * std::abs(y.center()));
    m_plot->yAxis->setRange(y.lower - pad, y.upper + pad);
    m_plot->replot();

    if (v.empty()) {
        m_drift->clear();
    } else {
        // One calibration has no spread and no drift: say what it is.
        const auto d = core::calibration::summarizeDrift(t, v);
        QString text =
            d.count == 1
                ? tr("%1: one calibration, %2").arg(title, fixedText(d.mean, decimals))
                : tr("%1 over %2: mean %3, SD %4; newest %5 % against the first")
                      .arg(title, countText(static_cast<long long>(d.count), tr("calibration"), tr("calibrations")))
                      .arg(fixedText(d.mean, decimals), significant(d.standardDeviation, 2),
                           fixedText(100.0 * d.firstToLast, 2));
        // A trend with its uncertainty, in the quantity's unit; a span or a
        // count too small for one says what one needs.
        if (d.trend)
            text += tr("; trend %1%2 per year")
                        .arg(valueWithErrorText(d.trend->perYear, d.trend->uncertaintyPerYear),
                             unit.isEmpty() ? QString() : QLatin1Char(' ') + unit);
        else if (d.count > 1)
            text +=
                tr("; no trend from %1 over %2 (one needs %3 over %4 days)")
                    .arg(countText(static_cast<long long>(d.count), tr("record"), tr("records")), spanText(d.span_s))
                    .arg(core::calibration::kTrendRecords)
                    .arg(core::calibration::kTrendSpan_s / 86400.0);
        m_drift->setText(text + QLatin1Char('.'));
        m_drift->setToolTip(m_drift->text());  // whole, should a narrow window cut the second line
    }
    if (!m_shown.empty()) m_records->selectRow(static_cast<int>(m_shown.size()) - 1);
    showSessions();
}

void CalibrationHistory::showSessions()
{
    m_sessions->clear();
    const int row = m_records->currentRow();
    if (row < 0 || row >= static_cast<int>(m_shown.size())) return;
    try {
        core::storage::SessionStore store(m_storePath.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto ids = store.sessionsUsingCalibration(m_shown[static_cast<std::size_t>(row)]->id);
        for (std::int64_t id : ids) {
            const auto session = store.session(id);
            if (!session) continue;
            m_sessions->addItem(tr("Session %1 — %2, %3, %4")
                                    .arg(id)
                                    .arg(screenDateTime(session->startedUtc),
                                         QString::fromStdString(session->metadata.subject),
                                         wordText(session->metadata.mode)));
        }
        if (ids.empty()) m_sessions->addItem(tr("none yet"));
    } catch (const core::storage::StorageError& e) {
        m_sessions->addItem(tr("cannot be read: %1").arg(QString::fromStdString(e.what())));
    }
}

}  // namespace tactiscope::ui
