// ReviewWindow: header, plot, record list, notes, replay, re-analysis and exports.
#include "ui/review/ReviewWindow.h"

#include "core/timing/ClockMappingJson.h"
#include "core/timing/ClockMappingText.h"
#include "ui/common/DateText.h"

#include "core/modes/ModeDefinition.h"
#include "core/storage/OpenSessionSource.h"

#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/VocabularyText.h"
#include "ui/live/VerdictDialog.h"

#include "core/detector/DefectSites.h"
#include "core/report/PressTable.h"
#include "core/report/ReportData.h"
#include "core/report/VerdictTrail.h"
#include "core/signal/SignalColumns.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/SafeOutput.h"
#include "core/storage/SessionExport.h"
#include "core/storage/StoredSites.h"
#include "ui/calibration/WizardText.h"
#include "ui/modes/ModeUi.h"
#include "ui/report/ReportDocument.h"
#include "ui/report/ReportPages.h"
#include "ui/review/ReviewAccount.h"
#include "ui/review/ReviewActions.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/SessionTableModel.h"
#include "ui/signal/ReviewFilterDialog.h"
#include "ui/signal/ReviewSpectrum.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPrintDialog>
#include <QPrinter>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTextDocument>
#include <QToolBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tactiscope::ui {
namespace {

// A verdict's time in the trail, as the window writes every date.
std::string screenTimeOf(const std::string& utc)
{
    return screenDateTime(utc).toStdString();
}

// A spin box takes Space as text (and refuses it): the window's Space
// shortcut (play, pause) is let through instead.
class SpaceForShortcuts : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::ShortcutOverride && static_cast<QKeyEvent*>(event)->key() == Qt::Key_Space) {
            event->ignore();  // not the box's: the shortcut takes it
            return true;
        }
        return QObject::eventFilter(watched, event);
    }
};

using core::storage::SessionSource;

const QColor kAThenB(217, 95, 2, 170);
const QColor kBThenA(117, 112, 179, 170);
const QColor kOtherEvent(120, 120, 120, 170);
const QColor kReading(27, 158, 119, 150);
const QColor kNote(60, 60, 60, 200);

enum Role { TimeRole = Qt::UserRole, EndRole, NoteRole };

QString text(const std::string& s)
{
    return QString::fromStdString(s);
}

QColor eventColour(const core::storage::SessionEvent& e)
{
    if (e.kind != core::EventKind::Defect) return kOtherEvent;
    return e.direction > 0 ? kAThenB : kBThenA;
}

QString eventDetails(const core::storage::SessionEvent& e)
{
    if (e.kind != core::EventKind::Defect) return text(e.note);
    QStringList parts{e.direction > 0 ? QObject::tr("A then B") : QObject::tr("B then A")};
    if (e.peakR) parts << QObject::tr("R = %1").arg(fixedText(*e.peakR, 3));
    if (e.lag_s) parts << QObject::tr("lag %1 ms").arg(fixedText(*e.lag_s * 1e3, 0));
    if (e.speed_m_per_s) parts << QObject::tr("%1 mm/s").arg(fixedText(*e.speed_m_per_s * 1e3, 0));
    parts << QObject::tr("%1 s long").arg(fixedText(e.end_s - e.start_s, 3));
    return parts.join(QStringLiteral(", "));
}

// Each defect's site ("site 2 (31.4 ± 1.2 mm)"), by its index among the defects:
// a reciprocating scan crosses one defect again and again.
std::vector<QString> siteTexts(core::storage::SessionSource& store, std::int64_t session,
                               const std::vector<core::detector::DefectEvent>& defects)
{
    std::vector<QString> texts(defects.size());
    const auto grouping = core::storage::storedSites(store, session, defects);
    for (std::size_t k = 0; k < grouping.sites.size(); ++k) {
        const auto& site = grouping.sites[k];
        const QString text = site.kind == core::detector::SiteKind::Unplaced
                                 ? QObject::tr("site %1").arg(k + 1)
                                 : QObject::tr("site %1 (%2)")
                                       .arg(k + 1)
                                       .arg(QString::fromStdString(core::detector::sitePlaceText(site, true)));
        for (const std::size_t i : site.crossings) texts[i] = text;
        for (const std::size_t i : site.parts) texts[i] = text;
    }
    return texts;
}

QString readingDetails(const core::storage::SessionReading& r)
{
    QString value;
    if (r.standardError) {
        const auto [number, error] = valueAndErrorTexts(r.value, *r.standardError);
        value = QObject::tr("%1 = %2 ± %3").arg(text(r.quantity), number, error);
    } else {
        value = QObject::tr("%1 = %2").arg(text(r.quantity)).arg(significantText(r.value, 5));
    }
    value += QLatin1Char(' ') + text(r.unit);
    if (!r.site.empty()) value += QObject::tr(" at %1").arg(text(r.site));
    return value;
}

struct Entry {
    double time_s;
    double end_s;
    QString what;
    QString source;
    QString details;
    std::int64_t note = 0;
};

}  // namespace

ReviewWindow* ReviewWindow::open(const QString& storePath, std::int64_t session, QWidget* parent, QString& error)
{
    try {
        std::unique_ptr<SessionSource> store;
        try {
            store = core::storage::openSessionSource(storePath.toStdString());
        } catch (const core::storage::StorageError&) {
            // A store on read-only media can still be reviewed; saving notes then says why it cannot.
            store =
                core::storage::openSessionSource(storePath.toStdString(), core::storage::Database::Access::ReadOnly);
        }
        auto summary = store->session(session);
        if (!summary) {
            error = tr("There is no session %1 in %2.").arg(session).arg(storePath);
            return nullptr;
        }
        if (summary->sampleCount == 0 || summary->sampleRate_hz <= 0.0) {
            error = tr("Session %1 holds no samples to review.").arg(session);
            return nullptr;
        }
        return new ReviewWindow(storePath, std::move(store), std::move(*summary), parent);
    } catch (const core::storage::StorageError& e) {
        error = tr("The store cannot be opened: %1").arg(text(e.what()));
        return nullptr;
    }
}

ReviewWindow::ReviewWindow(const QString& storePath, std::unique_ptr<SessionSource> store,
                           core::storage::SessionSummary session, QWidget* parent)
    : QMainWindow(parent),
      m_storePath(storePath),
      m_store(std::move(store)),
      m_session(std::move(session)),
      m_parts(m_store->parts(m_session.id))
{
    setAttribute(Qt::WA_DeleteOnClose);
    setWindowFlag(Qt::Window);
    setObjectName(QStringLiteral("reviewWindow"));
    const auto& meta = m_session.metadata;
    setWindowTitle(tr("Review: session %1 — %2 %3").arg(m_session.id).arg(wordText(meta.mode), text(meta.subject)));

    m_header = wrappedLabel({}, this);
    m_header->setObjectName(QStringLiteral("sessionHeader"));
    refreshHeader();
    m_problem = wrappedLabel({}, this);
    m_problem->setObjectName(QStringLiteral("problemText"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->hide();

    m_plot = new ReviewPlot(*m_store, m_session, m_laneOptions, this);
    m_list = new QTreeWidget(this);
    m_list->setObjectName(QStringLiteral("recordList"));
    m_list->setHeaderLabels({tr("Time (s)"), tr("What"), tr("Source"), tr("Details")});
    m_list->setRootIsDecorated(false);
    m_list->setAlternatingRowColors(true);
    m_list->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_list->header()->setStretchLastSection(true);
    auto* bottom = new QSplitter(Qt::Horizontal, this);
    bottom->addWidget(m_list);
    // The mode's own account beside the list (ui/modes/ModeUi.h); a mode
    // without one (general), and a session of several devices (each
    // device's analysis is its own part's), have the list alone.
    if (const auto account = m_parts.empty() ? modeUi(meta.mode).reviewAccount : nullptr) {
        const ReviewAccountContext context{
            storePath, *m_store, m_session,
            [this](const std::function<void(core::derived::LaneOptions&)>& change) { return changeLanes(change); },
            m_plot->derivedProblem()};
        m_account = account(context, this);
        connect(m_account, &ReviewAccount::recordsChanged, this, &ReviewWindow::recordsChanged);
        connect(m_account, &ReviewAccount::spanChosen, this, [this](double start_s, double end_s) {
            m_plot->centreOn(0.5 * (start_s + end_s), std::max(2.0, 2.0 * (end_s - start_s)));
            m_plot->setCursorTime(start_s);
        });
        connect(m_account, &ReviewAccount::problem, this, &ReviewWindow::showProblem);
        connect(m_account, &ReviewAccount::status, this,
                [this](const QString& text) { statusBar()->showMessage(text); });
        // Its controls stay reachable however low the panel is: it scrolls.
        auto* room = new QScrollArea(this);
        room->setObjectName(QStringLiteral("accountScroll"));
        room->setWidget(m_account);
        room->setWidgetResizable(true);
        room->setFrameShape(QFrame::NoFrame);
        // Up and down only: across, it keeps the width its contents need
        // (a palpation's scale and its labels), as it did unscrolled.
        room->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        room->setMinimumWidth(m_account->minimumSizeHint().width() + room->verticalScrollBar()->sizeHint().width());
        bottom->addWidget(room);
    }
    const bool accountFirst = m_account && m_account->wantsRoom();
    bottom->setStretchFactor(0, accountFirst ? 2 : 3);
    bottom->setStretchFactor(1, accountFirst ? 3 : 2);
    bottom->setSizes(accountFirst ? QList<int>{460, 740} : QList<int>{720, 480});
    auto* split = new QSplitter(Qt::Vertical, this);
    auto* top = new QWidget(this);
    auto* topLayout = new QVBoxLayout(top);
    topLayout->setContentsMargins(6, 6, 6, 0);
    topLayout->addWidget(m_header);
    topLayout->addWidget(m_problem);
    topLayout->addWidget(m_plot, 1);
    split->addWidget(top);
    split->addWidget(bottom);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    // Neither side collapses at a drag: the lanes and the panel scroll.
    split->setChildrenCollapsible(false);
    bottom->setChildrenCollapsible(false);
    const int line = fontMetrics().height();
    top->setMinimumHeight(8 * line);
    bottom->setMinimumHeight(8 * line);
    setCentralWidget(split);
    // 1200 × 860 where the screen has room; on a laptop's 1366 × 768, what
    // it has (the frame and a task bar left to it).
    const QScreen* screen = parent ? parent->screen() : QGuiApplication::primaryScreen();
    const QSize room = screen ? screen->availableGeometry().size() - QSize(16, 48) : QSize(1200, 860);
    resize(QSize(1200, 860).boundedTo(room));

    m_replay.setInterval(40);
    connect(&m_replay, &QTimer::timeout, this, &ReviewWindow::advanceReplay);
    watchPlot();
    if (!m_plot->derivedProblem().empty())
        showProblem(tr("The physical quantities cannot be computed (%1): the stored channels are shown.")
                        .arg(text(m_plot->derivedProblem())));
    connect(m_list, &QTreeWidget::itemClicked, this, &ReviewWindow::jumpTo);
    connect(m_list, &QTreeWidget::itemActivated, this, &ReviewWindow::jumpTo);
    connect(m_list, &QTreeWidget::itemDoubleClicked, this, &ReviewWindow::editSelectedNote);
    createActions();
    refreshRecords();
    if (m_session.station.empty())
        statusBar()->showMessage(tr("Session %1 of %2").arg(m_session.id).arg(QFileInfo(storePath).fileName()));
    else
        statusBar()->showMessage(tr("Session %1 of station %2, from the central store (%3)")
                                     .arg(m_session.stationId)
                                     .arg(text(m_session.station), text(m_store->location())));
}

ReviewWindow::~ReviewWindow() = default;

void ReviewWindow::setRawChannels(bool raw)
{
    changeLanes([raw](core::derived::LaneOptions& options) { options.raw = raw; });
}

bool ReviewWindow::rebuildPlot()
{
    const double from_s = m_plot->from_s(), to_s = m_plot->to_s();
    const auto cursor = m_plot->cursorTime();
    ReviewPlot* plot = nullptr;
    try {
        plot = new ReviewPlot(*m_store, m_session, m_laneOptions, this);
    } catch (const core::storage::StorageError& e) {
        showProblem(tr("The samples cannot be read: %1").arg(text(e.what())));
        return false;
    }
    delete m_plot->parentWidget()->layout()->replaceWidget(m_plot, plot);  // the old item is ours to delete
    delete m_plot;
    m_plot = plot;
    watchPlot();
    refreshRecords();  // the markers
    m_plot->setRange(from_s, to_s);
    if (cursor) m_plot->setCursorTime(*cursor);
    return true;
}

// The session's stored channels, by the names its lanes have.
void ReviewWindow::addReviewFilter()
{
    std::vector<ReviewFilterDialog::Channel> channels;
    try {
        if (m_parts.empty()) {
            for (const auto& c : m_store->channels(m_session.id))
                channels.push_back({c.descriptor.name, c.sampleRate_hz});
        } else {
            for (const auto& part : m_parts)
                for (const auto& c : m_store->channels(part.id))
                    channels.push_back({part.deviceName + "/" + c.descriptor.name, c.sampleRate_hz});
        }
    } catch (const core::storage::StorageError& e) {
        showProblem(tr("The channels cannot be read: %1").arg(text(e.what())));
        return;
    }
    ReviewFilterDialog dialog(std::move(channels), this);
    if (dialog.exec() != QDialog::Accepted) return;
    const auto filter = dialog.filter();
    if (!filter) return;
    const QString problem =
        changeLanes([&](core::derived::LaneOptions& options) { options.reviewFilters.push_back(*filter); });
    if (!problem.isEmpty()) showProblem(problem);
    m_clearFilters->setEnabled(!m_laneOptions.reviewFilters.empty());
    refreshHeader();
}

QString ReviewWindow::changeLanes(const std::function<void(core::derived::LaneOptions&)>& change)
{
    const core::derived::LaneOptions before = m_laneOptions;
    change(m_laneOptions);
    if (!rebuildPlot()) {
        m_laneOptions = before;
        return tr("The plot could not be redrawn through these options.");
    }
    if (!m_plot->derivedProblem().empty()) return text(m_plot->derivedProblem());
    return {};
}

void ReviewWindow::refreshHeader()
{
    const auto& meta = m_session.metadata;
    const bool interrupted = m_session.status == core::SessionStatus::Interrupted;
    // Only what the session holds: an empty field says nothing.
    QStringList header{tr("<b>%1</b>").arg(wordText(meta.mode).toHtmlEscaped())};
    const auto add = [&header](const QString& format, const std::string& value) {
        if (!value.empty()) header << format.arg(text(value).toHtmlEscaped());
    };
    add(tr("subject <b>%1</b>"), meta.subject);
    add(tr("operator %1"), meta.operatorName);
    add(tr("site %1"), meta.site);
    add(tr("triggered on %1"), meta.trigger);
    header << tr("started %1").arg(screenDateTime(m_session.startedUtc));
    if (m_parts.empty()) {
        header << tr("%1 at %2 Hz").arg(durationText(m_session.duration_s())).arg(typedText(m_session.sampleRate_hz));
        add(tr("device %1"), (meta.deviceModel + " " + meta.deviceSerial).substr(meta.deviceModel.empty() ? 1 : 0));
    } else {
        QStringList devices;
        for (const auto& part : m_parts) {
            const auto channels = m_store->channels(part.id);
            devices << tr("%1 at %2 Hz")
                           .arg(text(part.deviceName).toHtmlEscaped())
                           .arg(typedText(channels.empty() ? 0.0 : channels.front().sampleRate_hz));
        }
        header << tr("%1 on the session's clock: %2")
                      .arg(durationText(m_session.duration_s()))
                      .arg(devices.join(QStringLiteral(", ")));
    }
    header << (interrupted ? tr("<span style='color:#a05000'><b>interrupted</b> (kept up to the cut)</span>")
                           : tr("status %1").arg(wordText(m_session.status)));
    add(tr("verdict <b>%1</b>"), std::string(core::verdictText(m_session.verdict)));
    if (!m_session.verdict && !m_session.unjudged.empty())
        add(tr("no verdict: %1"), core::storage::unjudgedReason(m_session.unjudged));
    QStringList trail;
    if (m_session.verdict && !m_session.unjudged.empty())
        trail << text(core::report::unjudgedTrailLine(m_session.unjudged));
    try {
        for (const auto& line : core::report::verdictTrailLines(m_store->verdicts(m_session.id), screenTimeOf))
            trail << text(line);
    } catch (const core::storage::StorageError& e) {
        trail << tr("the verdict's trail cannot be read: %1").arg(text(e.what()));
    }
    // The last decision says who the verdict is whose; the whole trail is a hover away.
    if (!trail.isEmpty()) header.back() += QStringLiteral(" (%1)").arg(trail.back().toHtmlEscaped());
    // The reviewer's filters, by their lanes' names.
    const auto laneNames = core::signal::reviewFilterLaneNames(m_laneOptions.reviewFilters);
    for (std::size_t k = 0; k < laneNames.size(); ++k)
        header << tr("in review %1: %2")
                      .arg(text(laneNames[k]).toHtmlEscaped(),
                           text(m_laneOptions.reviewFilters[k].settings.text()).toHtmlEscaped());
    m_header->setText(header.join(QStringLiteral(" · ")));
    m_header->setToolTip(trail.join(QLatin1Char('\n')));
}

void ReviewWindow::createActions()
{
    ReviewActions* a = new ReviewActions(this);
    QMenu* file = menuBar()->addMenu(tr("&Export"));
    file->addAction(a->report);
    connect(a->report, &QAction::triggered, this, [this] {
        exportWithDialog(tr("Save the inspection report"), tr("PDF (*.pdf)"), QStringLiteral("pdf"),
                         [this](const QString& path) { return exportReport(path); });
    });
    file->addAction(a->print);
    connect(a->print, &QAction::triggered, this, &ReviewWindow::printReport);
    file->addSeparator();
    file->addAction(a->plotImage);
    connect(a->plotImage, &QAction::triggered, this, [this] {
        exportWithDialog(tr("Save the plot"), tr("PNG image (*.png);;SVG drawing (*.svg)"), QStringLiteral("png"),
                         [this](const QString& path) { return savePlot(path); });
    });
    file->addAction(a->csvWhole);
    connect(a->csvWhole, &QAction::triggered, this, [this] {
        exportWithDialog(tr("Export the session"), tr("CSV (*.csv)"), QStringLiteral("csv"),
                         [this](const QString& path) { return exportCsv(path, false); });
    });
    file->addAction(a->csvShown);
    connect(a->csvShown, &QAction::triggered, this, [this] {
        exportWithDialog(tr("Export the range shown"), tr("CSV (*.csv)"), QStringLiteral("csv"),
                         [this](const QString& path) { return exportCsv(path, true); });
    });
    file->addSeparator();
    file->addAction(a->close);
    connect(a->close, &QAction::triggered, this, &QWidget::close);
    QMenu* signal = menuBar()->addMenu(tr("&Signal"));
    QAction* spectrum = signal->addAction(tr("&Spectrum of the range shown…"), this, [this] {
        auto* dialog = new ReviewSpectrum(*m_store, m_session, m_plot->from_s(), m_plot->to_s(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    spectrum->setObjectName(QStringLiteral("reviewSpectrumAction"));
    QAction* filter = signal->addAction(tr("&Filter a channel in review…"), this, &ReviewWindow::addReviewFilter);
    filter->setObjectName(QStringLiteral("reviewFilterAction"));
    m_clearFilters = signal->addAction(tr("&Remove the review filters"), this, [this] {
        changeLanes([](core::derived::LaneOptions& options) { options.reviewFilters.clear(); });
        m_clearFilters->setEnabled(false);
        refreshHeader();
    });
    m_clearFilters->setObjectName(QStringLiteral("reviewFiltersClearAction"));
    m_clearFilters->setEnabled(false);

    QToolBar* bar = addToolBar(tr("Review"));
    bar->setObjectName(QStringLiteral("reviewToolBar"));
    bar->setMovable(false);
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(a->wholeSession);
    connect(a->wholeSession, &QAction::triggered, this, [this] { m_plot->showWholeSession(); });
    bar->addAction(a->zoomIn);
    connect(a->zoomIn, &QAction::triggered, this, [this] { m_plot->zoom(0.5); });
    bar->addAction(a->zoomOut);
    connect(a->zoomOut, &QAction::triggered, this, [this] { m_plot->zoom(2.0); });
    if (m_plot->showsDerived()) {
        QAction* raw = bar->addAction(tr("Raw channels"), this, &ReviewWindow::setRawChannels);
        raw->setObjectName(QStringLiteral("rawChannelsAction"));
        raw->setCheckable(true);
        raw->setToolTip(tr("The channels as the probe sent them, instead of the physical quantities computed "
                           "from them (%1)")
                            .arg(text(m_plot->derivedBasis())));
    }
    bar->addSeparator();
    m_playAction = a->play;
    bar->addAction(m_playAction);
    connect(m_playAction, &QAction::triggered, this, [this] { isPlaying() ? pause() : play(); });
    m_speed = new QSpinBox(this);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    m_speed->setRange(1, 10);
    m_speed->setSuffix(tr("× real time"));
    m_speed->setToolTip(tr("Replay speed"));
    m_speed->installEventFilter(new SpaceForShortcuts(m_speed));  // Space plays even from the speed box
    bar->addWidget(m_speed);
    // "Play" and "Pause" in one width, so the bar does not jump when it flips.
    if (QWidget* button = bar->widgetForAction(m_playAction)) {
        const QFontMetrics metrics(button->font());
        button->setMinimumWidth(
            std::max(metrics.horizontalAdvance(tr("Play")), metrics.horizontalAdvance(tr("Pause"))) +
            button->sizeHint().width() - metrics.horizontalAdvance(m_playAction->text()));
    }
    bar->addSeparator();
    bar->addWidget(new QLabel(tr(" Reviewer "), bar));
    m_reviewer = new QLineEdit(QSettings().value(QStringLiteral("review/reviewer")).toString(), bar);
    m_reviewer->setObjectName(QStringLiteral("reviewerEdit"));
    m_reviewer->setPlaceholderText(tr("your name"));
    m_reviewer->setToolTip(tr("Who reviews: every note and verdict carries this name (remembered)"));
    m_reviewer->setMaximumWidth(160);
    connect(m_reviewer, &QLineEdit::editingFinished, this,
            [this] { QSettings().setValue(QStringLiteral("review/reviewer"), m_reviewer->text().trimmed()); });
    bar->addWidget(m_reviewer);
    bar->addAction(a->addNote);
    connect(a->addNote, &QAction::triggered, this, &ReviewWindow::addNote);
    a->deleteNote->setParent(m_list);  // Del in the list only
    m_list->addAction(a->deleteNote);
    connect(a->deleteNote, &QAction::triggered, this, &ReviewWindow::deleteSelectedNote);
    bar->addAction(a->undoDelete);
    connect(a->undoDelete, &QAction::triggered, this, [this] {
        const QString error = undoDelete();
        if (!error.isEmpty()) showProblem(error);
    });
    if (core::definitionOf(m_session.metadata.mode).detectsDefects) {  // the modes with a verdict
        bar->addAction(a->verdict);
        connect(a->verdict, &QAction::triggered, this, &ReviewWindow::askVerdict);
    } else {
        delete std::exchange(a->verdict, nullptr);
    }
    // What the store's rights forbid is disabled, with the reason, before
    // it would be refused.
    const core::storage::SessionSource::Rights rights = m_store->rights();
    const auto allowOnly = [](QAction* action, const std::string& refusal) {
        if (refusal.empty()) return;
        action->setEnabled(false);
        action->setToolTip(tr("Not here: %1").arg(QString::fromStdString(refusal)));
    };
    for (QAction* notes : {a->addNote, a->deleteNote, a->undoDelete}) allowOnly(notes, rights.noNotes);
    if (a->verdict) allowOnly(a->verdict, rights.noReviewerVerdict);
}

void ReviewWindow::refreshRecords()
{
    QStringList rows{tr("Recorded")};
    std::vector<MarkerSpan> spans;
    std::vector<Entry> entries;
    try {
        // A source's events and readings on its row of markers and in the list.
        const auto add = [&](const std::vector<core::storage::SessionEvent>& events,
                             const std::vector<core::storage::SessionReading>& readings, int row, const QString& source,
                             const QString& readingSource) {
            const auto sites = siteTexts(*m_store, m_session.id, core::storage::defectEventsOf(events));
            std::size_t crossing = 0;
            for (const auto& e : events) {
                spans.push_back({e.start_s, e.end_s, row, eventColour(e)});
                QString details = eventDetails(e);
                if (e.kind == core::EventKind::Defect) details = sites[crossing++] + QStringLiteral(": ") + details;
                entries.push_back({e.start_s, e.end_s, wordText(e.kind), source, details});
            }
            for (const auto& r : readings) {
                spans.push_back({r.start_s, r.end_s, row, kReading});
                entries.push_back({r.start_s, r.end_s, wordText(r.kind), readingSource, readingDetails(r)});
            }
        };
        const auto newRow = [&rows](const QString& name) {
            rows << name;
            return static_cast<int>(rows.size()) - 1;
        };
        add(m_store->events(m_session.id), {}, 0, tr("recorded"), {});
        std::vector<ReviewAccount::Readings> otherReadings;
        if (const auto unsaved = m_account ? m_account->unsaved() : std::nullopt) {
            add(unsaved->events, unsaved->readings, newRow(tr("Re-analysis")), tr("re-analysis"), tr("re-analysis"));
            if (!unsaved->readings.empty()) otherReadings.push_back({tr("re-analysis"), unsaved->readings});
        }
        for (const auto& analysis : m_store->analyses(m_session.id)) {
            if (analysis == core::storage::kLiveAnalysis) continue;
            // A probe's own decisions, recorded beside the workstation's: named as what they are.
            const QString source = analysis == core::storage::kProbeAnalysis ? tr("the probe's own")
                                                                             : tr("saved \"%1\"").arg(text(analysis));
            const auto readings = m_store->readings(m_session.id, analysis);
            add(m_store->events(m_session.id, analysis), readings, newRow(text(analysis)), source, source);
            if (!readings.empty()) otherReadings.push_back({source, readings});
        }
        // Each device's own record, on the session's clock, and how its
        // clock was mapped there.
        for (const auto& part : m_parts) {
            const auto clock = core::timing::clockMappingFromJson(part.clockJson);
            const auto onSession = [&clock](double t) { return clock ? clock->host_s(t) : t; };
            auto events = m_store->events(part.id);
            for (auto& e : events) {
                e.start_s = onSession(e.start_s);
                e.end_s = onSession(e.end_s);
            }
            auto readings = m_store->readings(part.id);
            for (auto& r : readings) {
                r.start_s = onSession(r.start_s);
                r.end_s = onSession(r.end_s);
            }
            const QString device = text(part.deviceName);
            add(events, readings, newRow(device), device, device);
            entries.push_back({onSession(0.0), onSession(0.0), tr("device"), device,
                               tr("clock: %1").arg(text(core::timing::clockMappingText(part.clockJson)))});
        }
        const auto recordedReadings = m_store->readings(m_session.id);
        add({}, recordedReadings, newRow(tr("Readings")), {}, tr("reading"));
        rows << tr("Notes");
        for (const auto& a : m_store->annotations(m_session.id)) {
            spans.push_back({a.time_s, a.time_s, static_cast<int>(rows.size()) - 1, kNote});
            entries.push_back({a.time_s, a.time_s, tr("note"), text(a.author),
                               text(a.text) + (a.modifiedUtc != a.createdUtc ? tr(" (edited)") : QString()), a.id});
        }
        if (m_account) m_account->showReadings(recordedReadings, otherReadings);
    } catch (const core::storage::StorageError& e) {
        showProblem(tr("The session's records cannot be read: %1").arg(text(e.what())));
    }
    m_plot->setMarkers(rows, spans);
    std::ranges::stable_sort(entries, {}, &Entry::time_s);
    m_list->clear();
    for (const Entry& entry : entries) {
        auto* item = new QTreeWidgetItem(m_list, {fixedText(entry.time_s, 3), entry.what, entry.source, entry.details});
        item->setData(0, TimeRole, entry.time_s);
        item->setData(0, EndRole, entry.end_s);
        item->setData(0, NoteRole, QVariant::fromValue<qint64>(entry.note));
        item->setTextAlignment(0, Qt::AlignRight | Qt::AlignVCenter);
        if (entry.note != 0) item->setToolTip(3, tr("Double-click to edit, Delete to remove"));
    }
}

void ReviewWindow::jumpTo(QTreeWidgetItem* item)
{
    if (!item) return;
    const double start_s = item->data(0, TimeRole).toDouble(), end_s = item->data(0, EndRole).toDouble();
    // Wide enough to see the record and what led up to it.
    m_plot->centreOn(0.5 * (start_s + end_s), std::max(2.0, 4.0 * (end_s - start_s)));
    m_plot->setCursorTime(start_s);
    m_list->setCurrentItem(item);
    m_list->scrollToItem(item, QAbstractItemView::PositionAtCenter);
}

QString ReviewWindow::author()
{
    const QString name = m_reviewer->text().trimmed();
    if (name.isEmpty()) {
        m_reviewer->setFocus();
        showProblem(tr("Type your name in the Reviewer box first: notes and verdicts carry who wrote them."));
    } else {
        QSettings().setValue(QStringLiteral("review/reviewer"), name);
    }
    return name;
}

void ReviewWindow::askVerdict()
{
    if (author().isEmpty()) return;
    QStringList trail;
    try {
        // As it is now: another station or the CLI may have decided since the window opened.
        if (const auto now = m_store->session(m_session.id)) m_session.verdict = now->verdict;
        for (const auto& line : core::report::verdictTrailLines(m_store->verdicts(m_session.id), screenTimeOf))
            trail << text(line);
    } catch (const core::storage::StorageError& e) {
        showProblem(tr("The verdict's trail cannot be read: %1").arg(text(e.what())));
        return;
    }
    const auto current = m_session.verdict.value_or(core::Verdict::Pass);
    const QString summary =
        m_session.verdict ? tr("The verdict is \"%1\".").arg(wordText(current)) : tr("The session has no verdict yet.");
    auto* dialog = new VerdictDialog(summary, {}, trail, current, this);
    connect(dialog, &VerdictDialog::decided, this, [this](core::Verdict verdict, const QString& note) {
        const QString error = decideVerdict(verdict, note);
        if (!error.isEmpty()) showProblem(error);
    });
    dialog->show();
}

QString ReviewWindow::decideVerdict(core::Verdict verdict, const QString& note)
{
    const QString name = author();
    if (name.isEmpty()) return tr("The verdict was not saved: type your name in the Reviewer box first.");
    try {
        core::storage::VerdictDecision decision;
        decision.role = core::VerdictRole::Reviewer;
        decision.verdict = verdict;
        decision.decidedBy = name.toStdString();
        decision.note = note.trimmed().toStdString();
        m_store->decideVerdict(m_session.id, decision);
        m_session.verdict = verdict;
    } catch (const core::storage::StorageError& e) {
        return tr("The verdict was not saved: %1").arg(text(e.what()));
    }
    refreshHeader();
    emit sessionChanged();
    statusBar()->showMessage(tr("Verdict \"%1\" saved by %2.").arg(wordText(verdict), name));
    return {};
}

void ReviewWindow::askNoteText(const QString& title, const QString& initial,
                               std::function<QString(const QString&)> apply)
{
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName(QStringLiteral("noteDialog"));
    // The time in the dialog's text, not only its title: a title bar cut it to "Note a….710 s".
    dialog->setWindowTitle(tr("Note"));
    dialog->setLabelText(title + QLatin1Char(':'));
    dialog->setMinimumWidth(dialog->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 36);
    dialog->setTextValue(initial);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QInputDialog::textValueSelected, this, [this, apply](const QString& value) {
        const QString error = apply(value);
        if (!error.isEmpty()) showProblem(error);
    });
    dialog->open();
}

void ReviewWindow::addNote()
{
    const double time_s = m_plot->cursorTime().value_or(0.5 * (m_plot->from_s() + m_plot->to_s()));
    askNoteText(tr("Note at %1 s").arg(fixedText(time_s, 3)), {},
                [this, time_s](const QString& value) { return addNoteAt(time_s, value); });
}

QString ReviewWindow::addNoteAt(double time_s, const QString& value)
{
    if (value.trimmed().isEmpty()) return tr("An empty note was not added.");
    const QString name = author();
    if (name.isEmpty()) return tr("The note was not added: type your name in the Reviewer box first.");
    try {
        core::storage::Annotation note;
        note.time_s = time_s;
        note.author = name.toStdString();
        note.text = value.trimmed().toStdString();
        m_store->addAnnotation(m_session.id, note);
    } catch (const core::storage::StorageError& e) {
        return tr("The note was not saved: %1").arg(text(e.what()));
    }
    recordsChanged();
    return {};
}

QString ReviewWindow::editNote(std::int64_t annotation, const QString& value)
{
    if (value.trimmed().isEmpty()) return deleteNote(annotation);
    try {
        m_store->updateAnnotation(annotation, value.trimmed().toStdString());
    } catch (const core::storage::StorageError& e) {
        return tr("The note was not saved: %1").arg(text(e.what()));
    }
    recordsChanged();
    return {};
}

QString ReviewWindow::deleteNote(std::int64_t annotation)
{
    try {
        const auto notes = m_store->annotations(m_session.id);
        const auto found = std::ranges::find(notes, annotation, &core::storage::Annotation::id);
        if (found == notes.end()) return tr("That note is gone already.");
        m_store->deleteAnnotation(annotation);
        m_deleted = *found;
    } catch (const core::storage::StorageError& e) {
        return tr("The note was not deleted: %1").arg(text(e.what()));
    }
    recordsChanged();
    statusBar()->showMessage(tr("Note deleted; Ctrl+Z brings it back."));
    return {};
}

QString ReviewWindow::undoDelete()
{
    if (!m_deleted) return tr("No deleted note to bring back.");
    try {
        m_store->addAnnotation(m_session.id, *m_deleted);
    } catch (const core::storage::StorageError& e) {
        return tr("The note was not brought back: %1").arg(text(e.what()));
    }
    m_deleted.reset();
    recordsChanged();
    return {};
}

void ReviewWindow::editSelectedNote()
{
    QTreeWidgetItem* item = m_list->currentItem();
    const std::int64_t id = item ? item->data(0, NoteRole).toLongLong() : 0;
    if (id == 0) return;
    askNoteText(tr("Edit the note at %1 s").arg(item->text(0)), item->text(3).remove(tr(" (edited)")),
                [this, id](const QString& value) { return editNote(id, value); });
}

void ReviewWindow::deleteSelectedNote()
{
    QTreeWidgetItem* item = m_list->currentItem();
    const std::int64_t id = item ? item->data(0, NoteRole).toLongLong() : 0;
    if (id == 0) return;
    const QString error = deleteNote(id);
    if (!error.isEmpty()) showProblem(error);
}

void ReviewWindow::setReplaySpeed(int speed)
{
    m_speed->setValue(speed);
}

void ReviewWindow::play()
{
    const double from_s = m_plot->from_s(), to_s = m_plot->to_s();
    if (m_playhead_s < from_s || m_playhead_s >= to_s) m_playhead_s = from_s;
    m_replayClock.start();
    m_replay.start();
    m_playAction->setText(tr("Pause"));
    m_plot->setPlayhead(m_playhead_s);
}

void ReviewWindow::pause()
{
    m_replay.stop();
    m_playAction->setText(tr("Play"));
}

// The playhead moves at speed× the time passed; the view follows once it
// reaches four fifths of the width, like a scope's roll mode.
void ReviewWindow::advanceReplay()
{
    const double elapsed_s = static_cast<double>(m_replayClock.restart()) * 1e-3;
    m_playhead_s += elapsed_s * m_speed->value();
    const double duration_s = m_session.duration_s();
    if (m_playhead_s >= duration_s) {
        m_playhead_s = duration_s;
        pause();
    }
    const double width_s = m_plot->to_s() - m_plot->from_s();
    if (m_playhead_s > m_plot->from_s() + 0.8 * width_s)
        m_plot->setRange(m_playhead_s - 0.8 * width_s, m_playhead_s + 0.2 * width_s);
    m_plot->setPlayhead(m_playhead_s);
}

QString ReviewWindow::exportReport(const QString& pdfPath)
{
    try {
        core::storage::refuseOverwriting(pdfPath.toStdString(), core::storage::storeFiles(m_store->location()));
        const auto report = core::report::gatherReport(*m_store, m_session.id);
        const int pages = writeReportPdf(report, pdfPath);
        statusBar()->showMessage(tr("Report saved to %1 (%2 pages).").arg(pdfPath).arg(pages));
    } catch (const std::exception& e) {
        return tr("The report was not saved: %1").arg(text(e.what()));
    }
    return {};
}

void ReviewWindow::printReport()
{
    try {
        const auto report = core::report::gatherReport(*m_store, m_session.id);
        QPrinter printer(QPrinter::HighResolution);
        printer.setDocName(tr("Inspection report, session %1").arg(m_session.id));
        QPrintDialog dialog(&printer, this);
        if (dialog.exec() != QDialog::Accepted) return;
        printPages(*buildReportDocument(report), printer);
    } catch (const std::exception& e) {
        showProblem(tr("The report was not printed: %1").arg(text(e.what())));
    }
}

QString ReviewWindow::exportCsv(const QString& csvPath, bool visibleRangeOnly)
{
    core::storage::ExportRange range;
    if (visibleRangeOnly) {
        const double rate_hz = m_session.sampleRate_hz;
        range.first = static_cast<std::uint64_t>(std::max(0.0, std::floor(m_plot->from_s() * rate_hz)));
        range.count = static_cast<std::uint64_t>(std::ceil(m_plot->to_s() * rate_hz)) + 1 - range.first;
    }
    std::vector<std::string> problems;
    try {
        // With the filtered and math channels it was recorded with (each
        // device's, in a session of several).
        std::string problem;
        const auto signal = core::signal::withRecordedSignal(*m_store, m_session.id, nullptr, problem);
        if (!problem.empty()) problems.push_back(problem);
        core::storage::exportSession(*m_store, m_session.id, core::storage::ExportFormat::Csv, csvPath.toStdString(),
                                     range, signal.get(), core::signal::recordedSignalOfParts(*m_store, problems));
    } catch (const core::storage::StorageError& e) {
        return tr("The CSV was not written: %1").arg(text(e.what()));
    }
    QString left;
    for (const auto& problem : problems) left += QStringLiteral(" ") + text(problem);
    statusBar()->showMessage(tr("Exported to %1, with its metadata (calibrations included) in %2.%3")
                                 .arg(csvPath, text(core::storage::metadataSidePath(csvPath.toStdString())), left));
    return {};
}

QString ReviewWindow::savePlot(const QString& imagePath)
{
    try {
        m_plot->saveImage(imagePath);
    } catch (const std::exception& e) {
        return tr("The plot was not saved: %1").arg(text(e.what()));
    }
    statusBar()->showMessage(tr("Plot saved to %1.").arg(imagePath));
    return {};
}

void ReviewWindow::exportWithDialog(const QString& title, const QString& filter, const QString& suffix,
                                    const std::function<QString(const QString&)>& write)
{
    QString subject = text(m_session.metadata.subject);
    subject.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_.-]+")), QStringLiteral("-"));
    const QString suggested = QStringLiteral("session-%1%2.%3")
                                  .arg(m_session.id)
                                  .arg(subject.isEmpty() ? QString() : QLatin1Char('-') + subject, suffix);
    QString path = QFileDialog::getSaveFileName(this, title, suggested, filter);
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + suffix;
    const QString error = write(path);
    if (!error.isEmpty()) showProblem(error);
}

void ReviewWindow::recordsChanged()
{
    refreshRecords();
    emit sessionChanged();
}

void ReviewWindow::watchPlot()
{
    connect(m_plot, &ReviewPlot::readFailed, this, [this](const QString& message) {
        showProblem(message);
        m_readProblem = message;
    });
    connect(m_plot, &ReviewPlot::samplesRead, this, [this] {
        if (!m_readProblem.isEmpty() && m_problem->text() == m_readProblem) m_problem->hide();
        m_readProblem.clear();
    });
}

void ReviewWindow::showProblem(const QString& message)
{
    logProblem({tr("Review of session %1").arg(m_session.id), message, {}, {}});
    m_problem->setText(message);
    m_problem->show();
}

}  // namespace tactiscope::ui
