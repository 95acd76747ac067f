// SessionBrowser: filters, table, open and delete.
#include "ui/review/SessionBrowser.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"

#include "core/modes/ModeDefinition.h"
#include "core/storage/OpenSessionSource.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/common/VocabularyText.h"

#include "ui/calibration/WizardText.h"
#include "ui/review/SessionTableModel.h"

#include <QCalendarWidget>
#include <QComboBox>
#include <QDateEdit>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace tactiscope::ui {
namespace {

using core::storage::SessionSource;

const QDate kAnyDate(2000, 1, 1);  // the date edits' "any" value

// Its keys, here once for the window and its entry in Help. (Enter opens:
// Open is the default button.) Functions: a standard key is the platform's,
// known only once the application runs.
QKeySequence openKeys()
{
    return QKeySequence(Qt::Key_Return);
}
QKeySequence deleteKeys()
{
    return QKeySequence(QKeySequence::Delete);
}
QKeySequence refreshKeys()
{
    return QKeySequence(QKeySequence::Refresh);
}

// A date edit at "any" (its minimum, 2000-01-01) opens its calendar on
// this month, not on January 2000.
class CalendarOnToday : public QObject {
public:
    explicit CalendarOnToday(QDateEdit* edit)
        : QObject(edit),
          m_edit(edit)
    {
        edit->calendarWidget()->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Show && m_edit->date() == kAnyDate) {
            const QDate today = QDate::currentDate();
            m_edit->calendarWidget()->setCurrentPage(today.year(), today.month());
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QDateEdit* m_edit;
};

QDateEdit* dateEdit(QWidget* parent, const QString& name)
{
    auto* edit = new QDateEdit(kAnyDate, parent);
    edit->setObjectName(name);
    edit->setMinimumDate(kAnyDate);
    edit->setSpecialValueText(QObject::tr("any"));
    edit->setCalendarPopup(true);
    edit->setDisplayFormat(QStringLiteral("yyyy-MM-dd"));
    new CalendarOnToday(edit);
    return edit;
}

// The start of a local day as the store's UTC timestamps write it.
std::string utcStartOf(const QDate& localDay)
{
    return QDateTime(localDay, QTime(0, 0), Qt::LocalTime)
        .toUTC()
        .toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss.zzzZ"))
        .toStdString();
}

QString describe(const core::storage::SessionSummary& s)
{
    return QObject::tr("#%1 %2 %3 (%4, %5)")
        .arg(s.id)
        .arg(wordText(s.metadata.mode), QString::fromStdString(s.metadata.subject), screenDateTime(s.startedUtc),
             durationText(s.duration_s()));
}

}  // namespace

SessionBrowser::Listing SessionBrowser::listSessions(SessionSource& store, core::storage::SessionFilter filter,
                                                     std::size_t limit)
{
    Listing listing;
    core::storage::SessionFilter everything;
    everything.limit = limit;
    const auto all = store.sessions(everything);
    listing.total = all.size();
    listing.capped = limit > 0 && all.size() == limit;
    for (const auto& s : all)
        if (s.verdict) listing.verdicts << wordText(s.verdict);
    filter.limit = limit;
    listing.shown = store.sessions(filter);
    return listing;
}

SessionBrowser::SessionBrowser(std::shared_ptr<core::storage::StoreWorker> store, QWidget* parent)
    : QDialog(parent),
      m_store(std::move(store)),
      m_storePath(QString::fromStdString(m_store->path())),
      m_central(core::storage::isCentralStoreAddress(m_store->path())),
      m_model(new SessionTableModel(this)),
      m_sorted(new QSortFilterProxyModel(this)),
      m_table(new QTableView(this)),
      m_search(new QLineEdit(this)),
      m_mode(new QComboBox(this)),
      m_status(new QComboBox(this)),
      m_verdict(new QComboBox(this)),
      m_station(new QComboBox(this)),
      m_from(dateEdit(this, QStringLiteral("fromDate"))),
      m_to(dateEdit(this, QStringLiteral("toDate"))),
      m_count(new QLabel(this)),
      m_problem(wrappedLabel({}, this)),
      m_open(new QPushButton(tr("&Open for review"), this)),
      m_delete(new QPushButton(tr("&Delete…"), this))
{
    setWindowTitle(m_central ? tr("Sessions — central store")
                             : tr("Sessions — %1").arg(QFileInfo(m_storePath).fileName()));
    setObjectName(QStringLiteral("sessionBrowser"));
    m_table->setObjectName(QStringLiteral("sessionTable"));
    m_search->setObjectName(QStringLiteral("searchEdit"));
    m_mode->setObjectName(QStringLiteral("modeFilter"));
    m_status->setObjectName(QStringLiteral("statusFilter"));
    m_verdict->setObjectName(QStringLiteral("verdictFilter"));
    m_station->setObjectName(QStringLiteral("stationFilter"));
    m_count->setObjectName(QStringLiteral("countText"));
    m_problem->setObjectName(QStringLiteral("problemText"));
    m_open->setObjectName(QStringLiteral("openButton"));
    m_delete->setObjectName(QStringLiteral("deleteButton"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->hide();

    m_search->setPlaceholderText(tr("Search subject, operator, site, notes, verdict, serial…"));
    m_search->setClearButtonEnabled(true);
    m_mode->addItem(tr("Any mode"));
    for (const auto& definition : core::modeDefinitions()) m_mode->addItem(wordText(definition.mode));
    m_status->addItem(tr("Any status"));
    for (const auto status :
         {core::SessionStatus::Complete, core::SessionStatus::Interrupted, core::SessionStatus::Recording})
        m_status->addItem(wordText(status), static_cast<int>(status));
    m_verdict->addItem(tr("Any verdict"));
    m_station->addItem(tr("Any station"));
    m_station->setToolTip(tr("Only the sessions recorded at this station"));
    m_station->setVisible(m_central);  // a station's own store holds its sessions only

    m_sorted->setSourceModel(m_model);
    m_sorted->setSortRole(SessionTableModel::kSortRole);
    m_table->setModel(m_sorted);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(SessionTableModel::Started, Qt::DescendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(SessionTableModel::Subject, QHeaderView::Stretch);
    // Where each session was recorded: only a central store holds several stations.
    m_table->setColumnHidden(SessionTableModel::Station, !m_central);
    m_table->horizontalHeader()->moveSection(SessionTableModel::Station, 1);

    auto* filters = new QHBoxLayout;
    filters->addWidget(m_search, 3);
    filters->addWidget(m_station);
    filters->addWidget(m_mode);
    filters->addWidget(m_status);
    filters->addWidget(m_verdict);
    filters->addWidget(new QLabel(tr("From"), this));
    filters->addWidget(m_from);
    filters->addWidget(new QLabel(tr("to"), this));
    filters->addWidget(m_to);

    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(m_open, QDialogButtonBox::ActionRole);
    buttons->addButton(m_delete, QDialogButtonBox::DestructiveRole);
    QPushButton* refresh = buttons->addButton(tr("&Refresh"), QDialogButtonBox::ResetRole);
    buttons->addButton(QDialogButtonBox::Close);
    m_open->setDefault(true);
    m_open->setToolTip(tr("Open each selected session in its own review window (Enter)"));
    refresh->setToolTip(tr("Read the store again (F5)"));

    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_count, 1);
    bottom->addWidget(buttons);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(filters);
    layout->addWidget(m_problem);
    layout->addWidget(m_table, 1);
    layout->addLayout(bottom);
    resize(1040, 560);

    m_searchDelay.setSingleShot(true);
    m_searchDelay.setInterval(200);
    connect(&m_searchDelay, &QTimer::timeout, this, &SessionBrowser::reload);
    connect(m_search, &QLineEdit::textChanged, this, [this] { m_searchDelay.start(); });
    for (QComboBox* box : {m_mode, m_status, m_verdict, m_station})
        connect(box, &QComboBox::currentIndexChanged, this, &SessionBrowser::reload);
    for (QDateEdit* edit : {m_from, m_to}) connect(edit, &QDateEdit::dateChanged, this, &SessionBrowser::reload);
    connect(m_table, &QTableView::doubleClicked, this, &SessionBrowser::openSelected);
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this, &SessionBrowser::updateButtons);
    connect(m_open, &QPushButton::clicked, this, &SessionBrowser::openSelected);
    connect(m_delete, &QPushButton::clicked, this, &SessionBrowser::deleteSelected);
    connect(refresh, &QPushButton::clicked, this, &SessionBrowser::reload);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(new QShortcut(deleteKeys(), m_table), &QShortcut::activated, this, &SessionBrowser::deleteSelected);
    connect(new QShortcut(refreshKeys(), this), &QShortcut::activated, this, &SessionBrowser::reload);
    reload();
}

QList<ShortcutRow> SessionBrowser::helpRows()
{
    return {{tr("Open the selected sessions for review"), keysText({openKeys()})},
            {tr("Delete the selected sessions"), keysText({deleteKeys()})},
            {tr("Refresh"), keysText({refreshKeys()})}};
}

void SessionBrowser::reload()
{
    m_problem->hide();
    if (!m_central && !QFileInfo::exists(m_storePath)) {
        m_problem->setText(tr("No session has been recorded into %1 yet.").arg(m_storePath));
        m_problem->show();
        showListing({});
        return;
    }
    core::storage::SessionFilter filter;
    filter.text = m_search->text().trimmed().toStdString();
    if (m_mode->currentIndex() > 0) filter.mode = core::modeFromString(m_mode->currentText().toStdString());
    // Asked of the store, so the newest 5 000 a central store sends are
    // all of this status (filtered after, an old interrupted session was
    // never found behind 5 000 newer complete ones).
    if (m_status->currentIndex() > 0) filter.status = static_cast<core::SessionStatus>(m_status->currentData().toInt());
    if (m_verdict->currentIndex() > 0) filter.verdict = core::verdictFromString(m_verdict->currentText().toStdString());
    if (m_station->currentIndex() > 0) filter.station = m_station->currentText().toStdString();
    if (m_from->date() != kAnyDate) filter.startedFrom = utcStartOf(m_from->date());
    if (m_to->date() != kAnyDate) filter.startedBefore = utcStartOf(m_to->date().addDays(1));
    const auto failed = [this](const QString& error) {
        showProblem(tr("The store cannot be read: %1").arg(error));
        if (m_central) {
            // A server away for a while: the rows stay as last read, and
            // the next Refresh connects again.
            m_count->setText(tr("The list is as last read; Refresh (F5) tries again"));
            updateButtons();
            return;
        }
        showListing({});
    };
    if (m_central) {
        // A server may be slow or away: the window never waits on it.
        m_count->setText(tr("Reading the central store…"));
        runOnStore(
            *m_store, this,
            [filter](SessionSource& store) {
                Listing listing = listSessions(store, filter, kCentralRows);
                listing.rights = store.rights();
                for (const std::string& station : store.stations()) listing.stations << QString::fromStdString(station);
                return listing;
            },
            [this](Listing listing) { showListing(std::move(listing)); }, failed);
        return;
    }
    try {
        const auto store =
            core::storage::openSessionSource(m_storePath.toStdString(), core::storage::Database::Access::ReadOnly);
        showListing(listSessions(*store, filter, 0));
    } catch (const core::storage::StorageError& e) {
        failed(QString::fromStdString(e.what()));
    }
}

void SessionBrowser::showListing(Listing listing)
{
    if (listing.rights) m_noDelete = listing.rights->noDelete;
    if (listing.total > 0) {  // an unread store keeps the choices
        fillChoices(m_verdict, listing.verdicts);
        if (m_central) fillChoices(m_station, listing.stations);
    }
    // The selection survives a reload (a verdict changed in a review); the
    // first row is selected when nothing was, so Enter opens it.
    const auto selected = selectedSessions();
    m_model->setSessions(std::move(listing.shown));
    for (int row = 0; row < m_sorted->rowCount(); ++row) {
        const QModelIndex index = m_sorted->index(row, 0);
        if (std::ranges::find(selected, index.data(SessionTableModel::kIdRole).toLongLong()) != selected.end())
            m_table->selectionModel()->select(index, QItemSelectionModel::Select | QItemSelectionModel::Rows);
    }
    if (!m_table->selectionModel()->hasSelection() && m_sorted->rowCount() > 0) m_table->selectRow(0);
    m_count->setText(listing.capped
                         ? tr("%1 of the newest %2 sessions (narrow the search or the dates for older ones)")
                               .arg(m_model->rowCount())
                               .arg(listing.total)
                         : tr("%1 of %2")
                               .arg(m_model->rowCount())
                               .arg(countText(static_cast<long long>(listing.total), tr("session"), tr("sessions"))));
    updateButtons();
}

// Keeps the chosen verdict (or station) while offering every one the store holds.
void SessionBrowser::fillChoices(QComboBox* box, const QStringList& values)
{
    QStringList unique = values;
    unique.removeDuplicates();
    unique.sort(Qt::CaseInsensitive);
    QStringList present;
    for (int i = 1; i < box->count(); ++i) present << box->itemText(i);
    if (present == unique) return;
    const QString chosen = box->currentIndex() > 0 ? box->currentText() : QString();
    const QSignalBlocker quiet(box);
    while (box->count() > 1) box->removeItem(1);
    box->addItems(unique);
    box->setCurrentIndex(std::max(0, box->findText(chosen)));
}

std::vector<std::int64_t> SessionBrowser::selectedSessions() const
{
    QModelIndexList rows = m_table->selectionModel()->selectedRows();
    std::ranges::sort(rows, [](const QModelIndex& a, const QModelIndex& b) { return a.row() < b.row(); });
    std::vector<std::int64_t> ids;
    for (const QModelIndex& row : rows) ids.push_back(row.data(SessionTableModel::kIdRole).toLongLong());
    return ids;
}

void SessionBrowser::openSelected()
{
    const auto ids = selectedSessions();
    if (!ids.empty()) emit openSessions(ids);
}

void SessionBrowser::deleteSelected()
{
    const auto ids = selectedSessions();
    if (ids.empty()) return;
    if (!m_noDelete.empty()) {  // Del, with the button disabled
        showProblem(tr("Not deleted: %1").arg(QString::fromStdString(m_noDelete)));
        return;
    }
    QStringList names;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const auto* s = m_model->summaryAt(row);
        if (std::ranges::find(ids, s->id) != ids.end()) names << describe(*s);
    }
    auto* box =
        new QMessageBox(QMessageBox::Warning, tr("Delete sessions"),
                        ids.size() == 1 ? tr("Delete this session?") : tr("Delete these %1 sessions?").arg(ids.size()),
                        QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("deleteConfirmBox"));
    box->setInformativeText(names.join(QLatin1Char('\n')) +
                            tr("\n\nTheir samples, events, readings and annotations are removed for good. This "
                               "cannot be undone; export a session first to keep a copy."));
    QPushButton* confirm = box->addButton(tr("Delete"), QMessageBox::DestructiveRole);
    confirm->setObjectName(QStringLiteral("confirmDeleteButton"));
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(confirm, &QPushButton::clicked, this, [this, ids] { deleteSessions(ids); });
    box->open();
}

void SessionBrowser::deleteSessions(const std::vector<std::int64_t>& sessions)
{
    struct Outcome {
        std::vector<std::int64_t> deleted;
        QStringList refused;
    };
    emit deletingSessions(sessions);
    m_deleting = true;
    updateButtons();
    m_count->setText(
        tr("Deleting %1…").arg(countText(static_cast<long long>(sessions.size()), tr("session"), tr("sessions"))));
    const auto finish = [this](const Outcome& outcome) {
        m_deleting = false;
        reload();
        if (!outcome.deleted.empty()) emit sessionsDeleted(outcome.deleted);
        if (!outcome.refused.isEmpty()) {
            showProblem(tr("Not deleted: %1").arg(outcome.refused.join(QStringLiteral("; "))));
        }
    };
    runOnStore(
        *m_store, this,
        [sessions](SessionSource& store) {
            Outcome outcome;
            for (const std::int64_t id : sessions) {
                try {
                    store.deleteSession(id);
                    outcome.deleted.push_back(id);
                } catch (const core::storage::StorageError& e) {
                    outcome.refused << tr("#%1: %2").arg(id).arg(QString::fromStdString(e.what()));
                }
            }
            return outcome;
        },
        finish,
        [finish](const QString& error) {
            finish({{}, {error}});
        });
}

// A problem of the store, logged and shown in the browser's own line.
void SessionBrowser::showProblem(const QString& message)
{
    logProblem({tr("Session browser"), message, {}, {}});
    m_problem->setText(message);
    m_problem->show();
}

void SessionBrowser::updateButtons()
{
    const bool any = m_table->selectionModel()->hasSelection();
    m_open->setEnabled(any);
    m_delete->setEnabled(any && !m_deleting && m_noDelete.empty());
    m_delete->setToolTip(m_noDelete.empty()
                             ? tr("Delete the selected sessions with their samples, events and annotations (Del)")
                             : tr("Not here: %1").arg(QString::fromStdString(m_noDelete)));
}

}  // namespace tactiscope::ui
