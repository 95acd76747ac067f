// ReviewWindows: the browser, the review windows and the interrupted report.
#include "ui/review/ReviewWindows.h"

#include "ui/InterruptedSessionsReport.h"
#include "ui/ProblemReport.h"
#include "ui/review/ReviewWindow.h"
#include "ui/review/SessionBrowser.h"

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

void ReviewWindows::setStorePath(const QString& path)
{
    if (m_browser && path != m_storePath) m_browser->close();  // it lists the old store
    m_storePath = path;
}

SessionBrowser* ReviewWindows::showBrowser()
{
    if (!m_browser) {
        m_browser = new SessionBrowser(m_storePath, m_owner);
        m_browser->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_browser, &SessionBrowser::openSessions, this, &ReviewWindows::review);
        // A deleted session's review window has nothing left to show.
        connect(m_browser, &SessionBrowser::sessionsDeleted, this, [this](const std::vector<std::int64_t>& ids) {
            for (ReviewWindow* window : m_owner->findChildren<ReviewWindow*>())
                if (std::ranges::find(ids, window->sessionId()) != ids.end()) window->close();
        });
    }
    m_browser->show();
    m_browser->raise();
    m_browser->activateWindow();
    return m_browser;
}

void ReviewWindows::review(const std::vector<std::int64_t>& sessions)
{
    QStringList problems;
    for (const std::int64_t id : sessions) {
        const auto windows = m_owner->findChildren<ReviewWindow*>();
        const auto open = std::ranges::find(windows, id, &ReviewWindow::sessionId);
        ReviewWindow* window = open != windows.end() ? *open : nullptr;
        QString error;
        if (!window) window = ReviewWindow::open(m_storePath, id, m_owner, error);
        if (!window) {
            problems << error;
            continue;
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

void ReviewWindows::reportInterrupted()
{
    // Each interrupted session is reported once, on the first start after it.
    QSettings settings;
    const QString key =
        QStringLiteral("recording/interruptedReported/%1").arg(QFileInfo(m_storePath).absoluteFilePath());
    const auto sessions = interruptedSessionsAfter(m_storePath, settings.value(key, 0).toLongLong());
    if (sessions.empty()) return;
    settings.setValue(key, static_cast<qlonglong>(sessions.back()));
    showInterruptedSessionsReport(m_owner, m_storePath, sessions,
                                  [this](const std::vector<std::int64_t>& ids) { review(ids); });
}

void ReviewWindows::sessionRecorded()
{
    if (m_browser) m_browser->reload();
}

}  // namespace tactiscope::ui
