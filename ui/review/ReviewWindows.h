// The review side of the session store, as the main window offers it: the
// session browser (one at a time, closed when the store changes), a review
// window per session (an open one is raised, a deleted session's is closed),
// and the once-only report of sessions a crash cut short. The windows are
// children of `owner`, so they close with it.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

class QWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

class SessionBrowser;

class ReviewWindows : public QObject {
    Q_OBJECT

public:
    explicit ReviewWindows(QWidget* owner);

    // The window's store: its worker deletes sessions and finds the
    // interrupted ones (its read-write open marks them).
    void setStore(std::shared_ptr<core::storage::StoreWorker> store);
    SessionBrowser* showBrowser();
    // The browser of a site's central store (a connection of its own),
    // whose sessions open in review windows reading from the server.
    SessionBrowser* showCentralBrowser(const QString& conninfo);
    void review(const std::vector<std::int64_t>& sessions);  // of this station's store; failures are reported
    // After a start or a change of store: a damaged or unreadable store is
    // reported at once, and sessions a crash cut short are offered for review.
    void checkStore();
    void sessionRecorded();  // an open browser lists it

private:
    void reviewIn(const QString& storePath, const std::vector<std::int64_t>& sessions);
    void closeReviews(const QString& storePath, const std::vector<std::int64_t>& sessions);

    QWidget* m_owner;
    std::shared_ptr<core::storage::StoreWorker> m_store;
    QString m_storePath;
    QPointer<SessionBrowser> m_browser;         // of the current store, while open
    QPointer<SessionBrowser> m_centralBrowser;  // of the central store, while open
};

}  // namespace tactiscope::ui
