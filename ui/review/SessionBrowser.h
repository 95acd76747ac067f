// The session browser: every session of the store in a sortable table
// (SessionTableModel), narrowed by a search text, the mode, the status, the
// verdict and a date range; the store does the filtering (SessionFilter),
// so a store of thousands of sessions lists at once. Sessions are opened
// for review (several at a time) or deleted after a confirmation that
// names them; a session still being recorded cannot be deleted.
#pragma once

#include <QDialog>
#include <QTimer>

#include <cstdint>
#include <vector>

class QComboBox;
class QDateEdit;
class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace tactiscope::ui {

class SessionTableModel;

class SessionBrowser : public QDialog {
    Q_OBJECT

public:
    explicit SessionBrowser(const QString& storePath, QWidget* parent = nullptr);

    // Re-reads the store with the current filters.
    void reload();
    // The ids of the selected sessions, in the table's order.
    std::vector<std::int64_t> selectedSessions() const;
    // Opens the selected sessions (emits openSessions).
    void openSelected();
    // Asks, without blocking, to delete the selected sessions.
    void deleteSelected();
    QTableView* table() const { return m_table; }

signals:
    void openSessions(const std::vector<std::int64_t>& sessions);
    void sessionsDeleted(const std::vector<std::int64_t>& sessions);

private:
    void deleteSessions(const std::vector<std::int64_t>& sessions);
    void updateButtons();
    void fillChoices(QComboBox* box, const QStringList& values);

    QString m_storePath;
    SessionTableModel* m_model;
    QSortFilterProxyModel* m_sorted;
    QTableView* m_table;
    QLineEdit* m_search;
    QComboBox* m_mode;
    QComboBox* m_status;
    QComboBox* m_verdict;
    QDateEdit* m_from;
    QDateEdit* m_to;
    QLabel* m_count;
    QLabel* m_problem;
    QPushButton* m_open;
    QPushButton* m_delete;
    QTimer m_searchDelay;  // re-query once typing pauses, not per key
};

}  // namespace tactiscope::ui
