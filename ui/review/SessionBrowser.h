// The session browser: every session of the store in a sortable table
// (SessionTableModel), narrowed by a search text, the mode, the status, the
// verdict and a date range; the store does the filtering (SessionFilter),
// so a store of thousands of sessions lists at once. Sessions are opened
// for review (several at a time) or deleted after a confirmation that
// names them; a session still being recorded cannot be deleted. The list
// is read through a read-only open; deleting (which may remove millions of
// samples) runs on the window's store worker, off the GUI thread.
#pragma once

#include "ui/common/HelpWindows.h"

#include "core/storage/SessionSource.h"

#include <QDialog>
#include <QStringList>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <vector>

class QComboBox;
class QDateEdit;
class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

class SessionTableModel;

class SessionBrowser : public QDialog {
    Q_OBJECT

public:
    explicit SessionBrowser(std::shared_ptr<core::storage::StoreWorker> store, QWidget* parent = nullptr);

    // Re-reads the store with the current filters.
    void reload();
    // The ids of the selected sessions, in the table's order.
    std::vector<std::int64_t> selectedSessions() const;
    // Opens the selected sessions (emits openSessions).
    void openSelected();
    // Asks, without blocking, to delete the selected sessions; once they
    // are deleted, sessionsDeleted is emitted and the list reloaded.
    void deleteSelected();
    QTableView* table() const { return m_table; }
    // Its shortcuts for Help, from the keys it uses.
    static QList<ShortcutRow> helpRows();
    const QString& storePath() const { return m_storePath; }

signals:
    void openSessions(const std::vector<std::int64_t>& sessions);
    // Before the deletion starts: whatever shows these sessions closes.
    void deletingSessions(const std::vector<std::int64_t>& sessions);
    void sessionsDeleted(const std::vector<std::int64_t>& sessions);

private:
    // What a reload found: the sessions the filter keeps, how many the
    // store holds, and the verdicts it uses (for the verdict filter).
    struct Listing {
        std::vector<core::storage::SessionSummary> shown;
        std::size_t total = 0;
        bool capped = false;  // the store holds more than `total`
        QStringList verdicts;
        QStringList stations;                                        // a central store's, for the station filter
        std::optional<core::storage::SessionSource::Rights> rights;  // read with a central store's listing
    };
    // At most `limit` newest sessions (0: all): a central store may hold
    // millions, which no table should load at once.
    static Listing listSessions(core::storage::SessionSource& store, core::storage::SessionFilter filter,
                                std::size_t limit);
    static constexpr std::size_t kCentralRows = 5000;
    void showListing(Listing listing);
    void deleteSessions(const std::vector<std::int64_t>& sessions);
    void updateButtons();
    void showProblem(const QString& message);
    static void fillChoices(QComboBox* box, const QStringList& values);

    std::shared_ptr<core::storage::StoreWorker> m_store;
    QString m_storePath;
    bool m_central;  // a site's central store, not this station's file
    bool m_deleting = false;
    std::string m_noDelete;  // why this store's login may not delete, if it may not
    SessionTableModel* m_model;
    QSortFilterProxyModel* m_sorted;
    QTableView* m_table;
    QLineEdit* m_search;
    QComboBox* m_mode;
    QComboBox* m_status;
    QComboBox* m_verdict;
    QComboBox* m_station;  // a central store's only
    QDateEdit* m_from;
    QDateEdit* m_to;
    QLabel* m_count;
    QLabel* m_problem;
    QPushButton* m_open;
    QPushButton* m_delete;
    QTimer m_searchDelay;  // re-query once typing pauses, not per key
};

}  // namespace tactiscope::ui
