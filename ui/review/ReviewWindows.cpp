// ReviewWindows: the browser, the review windows and the interrupted report.
#include "ui/review/ReviewWindows.h"

#include "core/storage/StoreWorker.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/review/InterruptedSessionsReport.h"
#include "ui/review/ReviewWindow.h"
#include "ui/review/SessionBrowser.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QWidget>

#include <algorithm>

namespace tactiscope::ui {

ReviewWindows::ReviewWindows(QWidget* owner)
    : QObject(owner),
      m_owner(owner)
{
}

void ReviewWindows::setStore(std::shared_ptr<core::storage::StoreWorker> store)
{
    if (m_browser && store != m_store) m_browser->close();  // it lists the old store
    m_store = std::move(store);
    m_storePath = QString::fromStdString(m_store->path());
}

SessionBrowser* ReviewWindows::showBrowser()
{
    if (!m_browser) {
        m_browser = new SessionBrowser(m_store, m_owner);
        m_browser->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_browser, &SessionBrowser::openSessions, this, &ReviewWindows::review);
        // A deleted session's review window would have nothing left to show:
        // it closes before its samples go.
        connect(m_browser, &SessionBrowser::deletingSessions, this,
                [this](const std::vector<std::int64_t>& ids) { closeReviews(m_storePath, ids); });
    }
    m_browser->show();
    m_browser->raise();
    m_browser->activateWindow();
    return m_browser;
}

SessionBrowser* ReviewWindows::showCentralBrowser(const QString& conninfo)
{
    // Another server's browser goes: one central browser at a time.
    if (SessionBrowser* open = m_centralBrowser.data(); open != nullptr && open->storePath() != conninfo) {
        open->close();
        m_centralBrowser = nullptr;
    }
    if (!m_centralBrowser) {
        m_centralBrowser =
            new SessionBrowser(std::make_shared<core::storage::StoreWorker>(conninfo.toStdString()), m_owner);
        m_centralBrowser->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_centralBrowser, &SessionBrowser::openSessions, this,
                [this, conninfo](const std::vector<std::int64_t>& ids) { reviewIn(conninfo, ids); });
        connect(m_centralBrowser, &SessionBrowser::deletingSessions, this,
                [this, conninfo](const std::vector<std::int64_t>& ids) { closeReviews(conninfo, ids); });
    }
    m_centralBrowser->show();
    m_centralBrowser->raise();
    m_centralBrowser->activateWindow();
    return m_centralBrowser;
}

void ReviewWindows::closeReviews(const QString& storePath, const std::vector<std::int64_t>& sessions)
{
    for (ReviewWindow* window : m_owner->findChildren<ReviewWindow*>())
        if (window->storePath() == storePath && std::ranges::find(sessions, window->sessionId()) != sessions.end())
            window->close();
}

void ReviewWindows::review(const std::vector<std::int64_t>& sessions)
{
    reviewIn(m_storePath, sessions);
}

void ReviewWindows::reviewIn(const QString& storePath, const std::vector<std::int64_t>& sessions)
{
    QStringList problems;
    for (const std::int64_t id : sessions) {
        const auto windows = m_owner->findChildren<ReviewWindow*>();
        const auto open = std::ranges::find_if(
            windows, [&](const ReviewWindow* w) { return w->storePath() == storePath && w->sessionId() == id; });
        ReviewWindow* window = open != windows.end() ? *open : nullptr;
        QString error;
        if (!window) {
            window = ReviewWindow::open(storePath, id, m_owner, error);
            if (!window) {
                problems << error;
                continue;
            }
            // A verdict or note changed in the review shows in the browser at once.
            connect(window, &ReviewWindow::sessionChanged, this, [this, storePath] {
                SessionBrowser* browser = storePath == m_storePath ? m_browser.data() : m_centralBrowser.data();
                if (browser && browser->storePath() == storePath) browser->reload();
            });
        }
        window->show();
        window->raise();
    }
    if (!problems.isEmpty())
        reportProblem(m_owner,
                      {tr("Review"), tr("Not every session could be opened."), problems.join(QLatin1Char('\n')),
                       tr("Check that the session store is reachable, then open them again from the "
                          "session browser.")});
}

void ReviewWindows::checkStore()
{
    if (!QFileInfo::exists(m_storePath)) return;  // no store, no crash (and none is made here)
    // Each interrupted session is reported once, on the first start after it.
    const QString key =
        QStringLiteral("recording/interruptedReported/%1").arg(QFileInfo(m_storePath).absoluteFilePath());
    const std::int64_t reported = QSettings().value(key, 0).toLongLong();
    runOnStore(
        *m_store, this,
        [reported](core::storage::SessionSource& store) {
            store.refuseIfDamaged();
            return interruptedSessionsAfter(store, reported);
        },
        [this, key, store = m_store](const std::vector<core::storage::SessionSummary>& sessions) {
            if (sessions.empty()) return;
            QSettings().setValue(key, static_cast<qlonglong>(sessions.back().id));
            showInterruptedSessionsReport(m_owner, store, sessions,
                                          [this](const std::vector<std::int64_t>& ids) { review(ids); });
        },
        [this, path = m_storePath](const QString& error) {
            // Shown, not only logged: sessions recorded now would be lost
            // with the file or refused at Record.
            reportProblem(m_owner, {tr("Session store unusable"),
                                    tr("The session store %1 cannot be used.").arg(QDir::toNativeSeparators(path)),
                                    error, tr("Choose another store with Session ▸ Session store… before recording."),
                                    QStringLiteral("storeProblemBox")});
        });
}

void ReviewWindows::sessionRecorded()
{
    if (m_browser) m_browser->reload();
}

}  // namespace tactiscope::ui
