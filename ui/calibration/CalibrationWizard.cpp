// CalibrationWizard: the sensor, zero, loads and result pages every
// calibration shares, and storing its record off the GUI thread.
#include "ui/calibration/CalibrationWizard.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include "core/storage/SessionStore.h"
#include "ui/calibration/CalibrationPlot.h"
#include "ui/calibration/CapturePanel.h"
#include "ui/calibration/CheckedPage.h"
#include "ui/calibration/FitLimitsBox.h"
#include "ui/calibration/StabilityCriteria.h"
#include "ui/calibration/StabilityIndicator.h"
#include "ui/calibration/StabilityWatch.h"
#include "ui/calibration/WizardText.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/profiles/ActiveProfiles.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {

CalibrationWizard::CalibrationWizard(CalibrationContext context, Words words, QWidget* parent)
    : QWizard(parent),
      m_context(std::move(context)),
      m_words(std::move(words)),
      m_watch(new StabilityWatch(this))
{
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    setButtonText(QWizard::FinishButton, tr("&Accept and store"));
    resize(1060, 680);  // the six columns of loads beside the plot
    const QString mode = QString::fromUtf8(core::toString(m_words.mode));
    for (ProfileEntry& entry : ProfileLibrary(m_context.profileDirectory).entries(mode, activeProfile(mode).path))
        if (entry.profile && m_words.profileFits(*entry.profile)) m_profiles.push_back(std::move(entry));
    connect(m_watch, &StabilityWatch::captured, this, [this](const core::calibration::WindowStatistics& window) {
        if (auto use = std::exchange(m_onWindow, {})) use(window);
    });
}

void CalibrationWizard::addPages(const std::vector<std::pair<QString, QWidget*>>& sensorRows, CheckedPage* setupPage)
{
    setPage(SensorPage, createSensorPage(sensorRows));
    if (setupPage) setPage(SetupPage, setupPage);
    setPage(ZeroPage, createZeroPage());
    setPage(LoadsPage, createLoadsPage());
    setPage(ResultPage, createResultPage());
}

void CalibrationWizard::recheck(int id)
{
    static_cast<CheckedPage*>(page(id))->recheck();
}

CheckedPage* CalibrationWizard::createSensorPage(const std::vector<std::pair<QString, QWidget*>>& rows)
{
    // A record says who calibrated: none is stored without a name.
    auto* page = new CheckedPage(
        [this] { return m_channel->currentIndex() >= 0 && sensorChosen() && !operatorName().isEmpty(); });
    page->setTitle(tr("Channel and sensor"));
    page->setSubTitle(tr("Which channel, on which sensor, and who calibrates."));
    m_channel = new QComboBox(page);
    m_channel->setObjectName(QStringLiteral("channelBox"));
    for (std::size_t c = 0; c < m_context.channels.size(); ++c)
        if (m_words.channelFits(m_context.channels[c]))
            m_channel->addItem(QString::fromStdString(m_context.channels[c].name), static_cast<qulonglong>(c));
    m_profile = new QComboBox(page);
    m_profile->setObjectName(QStringLiteral("profileBox"));
    for (const ProfileEntry& entry : m_profiles) m_profile->addItem(entry.name, entry.path);
    m_operator = new QLineEdit(m_context.operatorName, page);
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_operator->setPlaceholderText(tr("who calibrates (required: stored with the record)"));
    connect(m_operator, &QLineEdit::textChanged, page, &CheckedPage::recheck);
    m_sensorSummary = wrappedLabel({}, page);
    m_sensorSummary->setObjectName(QStringLiteral("sensorSummary"));

    auto* form = new QFormLayout;
    form->addRow(m_words.channelLabel, m_channel);
    form->addRow(tr("&Sensor profile"), m_profile);
    for (const auto& [label, field] : rows) form->addRow(label, field);
    form->addRow(tr("&Operator"), m_operator);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(m_sensorSummary);
    if (m_channel->count() == 0) layout->addWidget(wrappedLabel(m_words.noChannel, page));
    if (m_profiles.empty())
        layout->addWidget(wrappedLabel(tr("<b>No profile of this sensor can be read.</b> Fix or choose one in "
                                          "Sensor ▸ Profiles."),
                                       page));
    layout->addStretch();
    return page;
}

CheckedPage* CalibrationWizard::createZeroPage()
{
    auto* page = new CheckedPage([this] { return m_zero.has_value(); });
    page->setTitle(tr("Zero"));
    page->setSubTitle(m_words.zeroSubTitle);
    auto* indicator = new StabilityIndicator(m_watch, page);
    indicator->setUnit(m_words.signal);
    m_criteria = new StabilityCriteria(m_words.signal, page);
    m_zeroText = new QLabel(page);
    m_zeroText->setObjectName(QStringLiteral("zeroText"));
    auto* retakeZero = new QPushButton(tr("Re&take zero"), page);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(indicator);
    layout->addWidget(m_criteria);
    layout->addWidget(m_zeroText);
    layout->addWidget(retakeZero, 0, Qt::AlignLeft);
    layout->addStretch();
    connect(m_criteria, &StabilityCriteria::edited, this, [this] {
        m_watch->setSettings(m_criteria->settings());
        if (currentId() == ZeroPage && !m_zero) takeZero();
    });
    connect(retakeZero, &QPushButton::clicked, this, &CalibrationWizard::takeZero);
    return page;
}

CheckedPage* CalibrationWizard::createLoadsPage()
{
    auto* page = new CheckedPage([this] { return m_fit.has_value() && !m_onWindow; });
    page->setTitle(tr("Known loads"));
    page->setSubTitle(m_words.loadsSubTitle);
    const QString unit = m_words.signal.symbol;
    m_panel = new CapturePanel(m_watch, m_words.signal, m_words.loadUnits,
                               {tr("Load"), tr("Direction"), tr("Force (mN)"), tr("Mean (%1)").arg(unit),
                                tr("σ (%1)").arg(unit), tr("Residual (% FS)")},
                               page);
    m_panel->setLoad(m_words.firstLoad.first, m_words.firstLoad.second);
    m_panel->setStatus(m_context.rig ? tr("Simulator: the rig places each load for you when you capture.") : QString());
    m_panel->plot()->setTitles(m_words.plotX.axisTitle(), m_words.plotY.axisTitle(),
                               tr("Residual (%1)").arg(m_words.plotY.symbol));
    m_panel->plot()->setSeriesNames(tr("zero and loading"), tr("unloading"));
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_panel);
    connect(m_panel, &CapturePanel::captureRequested, this, &CalibrationWizard::capture);
    connect(m_panel, &CapturePanel::retakeRequested, this, &CalibrationWizard::retake);
    connect(m_panel, &CapturePanel::removeRequested, this, &CalibrationWizard::remove);
    return page;
}

CheckedPage* CalibrationWizard::createResultPage()
{
    auto* page = new CheckedPage([this] { return credible() && !m_storing; });
    page->setTitle(tr("Result"));
    page->setSubTitle(m_words.resultSubTitle);
    m_resultText = wrappedLabel({}, page);
    m_resultText->setObjectName(QStringLiteral("resultText"));
    m_resultText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problems = wrappedLabel({}, page);
    m_problems->setObjectName(QStringLiteral("problemsText"));
    m_problems->setStyleSheet(QStringLiteral("color: #b00020"));
    m_limits = new FitLimitsBox(m_words.limits, page);
    m_resultLayout = new QVBoxLayout(page);
    m_resultLayout->addWidget(m_resultText);
    m_resultLayout->addWidget(m_problems);
    m_resultLayout->addWidget(m_limits);
    m_resultLayout->addStretch();
    connect(m_limits, &FitLimitsBox::changed, this, &CalibrationWizard::showResult);
    return page;
}

void CalibrationWizard::initializePage(int id)
{
    if (id == ZeroPage) {
        m_watch->setInput(m_context.buffer, chosenChannel());
        // The defaults follow the setup (an ADC's full scale); a user's own
        // criteria stay until the setup changes them.
        const auto defaults = stabilityDefaults();
        if (defaults != m_defaultsShown) m_criteria->setSettings(defaults);
        m_defaultsShown = defaults;
        m_watch->setSettings(m_criteria->settings());
        takeZero();
    }
    if (id == LoadsPage) refit();
    if (id == ResultPage) showResult();
    QWizard::initializePage(id);
}

void CalibrationWizard::cleanupPage(int id)
{
    if (id == LoadsPage || id == ZeroPage) {
        m_watch->disarm();
        m_onWindow = {};
        m_retakeIndex.reset();
        m_panel->setWaiting(false);
    }
    QWizard::cleanupPage(id);
}

const ProfileEntry* CalibrationWizard::chosenProfileEntry() const
{
    const int index = m_profile ? m_profile->currentIndex() : -1;
    if (index < 0 || index >= static_cast<int>(m_profiles.size())) return nullptr;
    return &m_profiles[static_cast<std::size_t>(index)];
}

std::size_t CalibrationWizard::chosenChannel() const
{
    return static_cast<std::size_t>(m_channel->currentData().toULongLong());
}

void CalibrationWizard::setSensorSummary(const QString& text)
{
    m_sensorSummary->setText(text);
}

QString CalibrationWizard::operatorName() const
{
    return m_operator->text().trimmed();
}

std::optional<QString> CalibrationWizard::refusal(const Load&) const
{
    return std::nullopt;
}

void CalibrationWizard::waitForWindow(const QString& status,
                                      std::function<void(const core::calibration::WindowStatistics&)> use)
{
    m_onWindow = std::move(use);
    m_panel->setStatus(status);
    m_panel->setWaiting(true);
    m_watch->arm();
    recheck(LoadsPage);
}

int CalibrationWizard::meanDecimals(const core::calibration::WindowStatistics& window) const
{
    const double error = window.meanStandardError * m_words.signal.scale;
    return error > 0.0 ? decimalsFor(error) : m_words.signalDecimals;
}

void CalibrationWizard::takeZero()
{
    if (m_context.rig) m_context.rig->place(0.0);
    m_zero.reset();
    m_zeroText->setText(tr("%1: waiting for a stable signal…").arg(m_words.zeroName));
    recheck(ZeroPage);
    m_onWindow = [this](const core::calibration::WindowStatistics& window) {
        m_zero = window;
        const DisplayUnit& u = m_words.signal;
        m_zeroText->setText(tr("%1: %2 %3, σ %4 %3 (mean of %5 samples)")
                                .arg(m_words.zeroName, fixedText(window.mean * u.scale, meanDecimals(window)), u.symbol,
                                     significant(window.sigma * u.scale, 3))
                                .arg(window.count));
        refit();
        recheck(ZeroPage);
    };
    m_watch->arm();
}

void CalibrationWizard::capture()
{
    Load load{m_panel->loadValue(), m_panel->loadUnit(), true, {}};
    if (load.value <= 0.0) {
        m_panel->setStatus(tr("Enter the load first: the zero is already taken."));
        m_retakeIndex.reset();
        return;
    }
    // Loading while the total grows, unloading once loads come off; a
    // retaken load keeps its direction.
    if (m_retakeIndex)
        load.loading = m_loads[*m_retakeIndex].loading;
    else if (!m_loads.empty())
        load.loading = forceOf(load) > forceOf(m_loads.back());
    if (m_context.rig) m_context.rig->place(forceOf(load));
    waitForWindow(tr("Waiting for a stable reading with %1 on the sensor…").arg(loadText(load)),
                  [this, load](const core::calibration::WindowStatistics& window) mutable {
                      load.window = window;
                      captured(load);
                  });
}

void CalibrationWizard::captured(Load load)
{
    m_panel->setWaiting(false);
    const DisplayUnit& u = m_words.signal;
    if (const auto why = refusal(load)) {
        m_panel->setStatus(*why);
    } else {
        if (m_retakeIndex && *m_retakeIndex < m_loads.size())
            m_loads[*m_retakeIndex] = load;
        else
            m_loads.push_back(load);
        m_panel->setStatus(tr("Captured %1: %2 %3 (σ %4).")
                               .arg(loadText(load), fixedText(load.window.mean * u.scale, meanDecimals(load.window)),
                                    u.symbol, significant(load.window.sigma * u.scale, 3)));
    }
    m_retakeIndex.reset();
    refit();
    m_panel->focusEntry();
}

void CalibrationWizard::retake(int row)
{
    const Load& load = m_loads.at(static_cast<std::size_t>(row));
    m_panel->setLoad(load.value, load.unit);
    m_retakeIndex = static_cast<std::size_t>(row);
    capture();
}

void CalibrationWizard::setLoads(std::vector<Load> loads)
{
    m_loads = std::move(loads);
    m_retakeIndex.reset();
    refit();
}

void CalibrationWizard::remove(int row)
{
    m_loads.erase(m_loads.begin() + row);
    refit();
}

QString CalibrationWizard::loadAndDirection(const Load& load) const
{
    return tr("%1, %2").arg(loadText(load), load.loading ? tr("loading") : tr("unloading"));
}

// The fitted points are the zero (0) and the loads (1…).
QString CalibrationWizard::pointName(std::size_t fitted) const
{
    if (fitted == 0) return tr("The zero");
    return tr("Load %1 (%2)").arg(fitted).arg(loadAndDirection(m_loads[fitted - 1]));
}

void CalibrationWizard::refit()
{
    m_fit.reset();
    if (m_zero && m_loads.size() >= 2) {
        try {
            m_fit = fitLoads();
        } catch (const std::invalid_argument& e) {
            m_panel->setFitSummary(tr("No fit: %1").arg(QString::fromStdString(e.what())));
        }
    }

    const QLocale locale;
    const DisplayUnit& u = m_words.signal;
    const std::vector<double> residuals =
        m_fit ? core::calibration::residualsOfSpan(m_fit->line.residuals, m_fit->y) : std::vector<double>{};
    // The means' column shares the decimals of its coarsest standard error.
    int decimals = 9;
    for (const Load& load : m_loads) decimals = std::min(decimals, meanDecimals(load.window));
    std::vector<QStringList> rows;
    for (std::size_t i = 0; i < m_loads.size(); ++i) {
        const Load& load = m_loads[i];
        rows.push_back({loadText(load), load.loading ? tr("loading") : tr("unloading"),
                        significant(forceOf(load) * 1e3, 5), fixedText(load.window.mean * u.scale, decimals),
                        significant(load.window.sigma * u.scale, 3),
                        i + 1 < residuals.size() ? fixedText(100.0 * residuals[i + 1], 3) : QStringLiteral("–")});
    }
    m_panel->setRows(rows, 2);

    std::vector<CalibrationPoint> points;
    if (m_fit) {
        const double xs = m_words.plotX.scale, ys = m_words.plotY.scale;
        for (std::size_t i = 0; i < m_fit->x.size(); ++i)
            points.push_back({m_fit->x[i] * xs, m_fit->y[i] * ys, i == 0 || m_loads[i - 1].loading});
        m_panel->plot()->setData(points, std::make_pair(m_fit->line.slope * ys / xs, m_fit->line.intercept * ys));
        m_panel->setFitSummary(m_fit->summary);
    } else {
        m_panel->plot()->setData(points, std::nullopt);
        if (m_loads.size() < 2) m_panel->setFitSummary(tr("Two loads are needed for a line."));
    }
    recheck(LoadsPage);
}

bool CalibrationWizard::credible() const
{
    return m_fit && core::calibration::judgeFit(m_fit->x, m_fit->y, m_limits->limits()).credible();
}

void CalibrationWizard::showResult()
{
    if (!m_fit) return;
    m_resultText->setText(resultHtml());
    const auto limits = m_limits->limits();
    const QStringList problems = FitLimitsBox::problems(core::calibration::judgeFit(m_fit->x, m_fit->y, limits), limits,
                                                        [this](std::size_t i) { return pointName(i); });
    m_problems->setText(problems.isEmpty() ? QString()
                                           : tr("Cannot be stored: %1").arg(problems.join(QLatin1Char(' '))));
    resultShown();
    recheck(ResultPage);
}

void CalibrationWizard::accept()
{
    if (!credible() || m_storing) return;
    core::calibration::CalibrationRecord made = record();
    made.operatorName = operatorName().toStdString();
    made.timestampUtc = core::calibration::utcTimestampNow();
    m_storing = true;  // Accept is off until the store has answered
    recheck(ResultPage);
    const QString sensor = QString::fromStdString(made.sensorName);
    runOnStore(
        *m_context.store, this, [made](core::storage::SessionSource& store) { return store.addCalibration(made); },
        [this, sensor](std::int64_t id) { stored(id, sensor); },
        [this](const QString& error) {
            m_storing = false;
            recheck(ResultPage);
            reportProblem(
                this,
                {tr("Calibration not stored"),
                 tr("The calibration could not be stored in %1.").arg(QString::fromStdString(m_context.store->path())),
                 error,
                 tr("The wizard stays open with every load: free space or fix the store's "
                    "permissions, then accept again.")});
        });
}

void CalibrationWizard::stored(std::int64_t id, const QString& sensor)
{
    m_storing = false;
    m_watch->disarm();
    emit calibrationStored(id, sensor);
    QWizard::accept();
}

}  // namespace tactiscope::ui
