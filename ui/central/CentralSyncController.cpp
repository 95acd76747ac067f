// CentralSyncController: one push at a time on a worker thread; results
// come back to the GUI thread queued on this object.
#include "ui/central/CentralSyncController.h"

#include "core/storage/central/CentralSync.h"
#include "ui/common/NumberText.h"

#include <QFileInfo>
#include <QMetaObject>
#include <QSettings>

#include <utility>

namespace tactiscope::ui {

namespace {

// The CLI's line in the window's words: counts in full and in the locale,
// one session singular ("synced 1 session (8,000 samples), 3 already
// there", not "1 sessions (0.0080 M samples)").
QString syncText(const core::storage::central::SyncOutcome& outcome)
{
    return QObject::tr("synced %1 (%2), %3 already there")
        .arg(countText(outcome.sent, QObject::tr("session"), QObject::tr("sessions")),
             countText(static_cast<long long>(outcome.samplesSent), QObject::tr("sample"), QObject::tr("samples")))
        .arg(outcome.alreadyThere);
}
const QString kServerKey = QStringLiteral("central/server");
const QString kStationKey = QStringLiteral("central/station");
}  // namespace

struct CentralSyncController::Result {
    QString outcome;
    QString error;
    bool unreachable = false;
    int sent = 0;
    std::optional<int> waiting;
};

CentralSyncController::CentralSyncController(QObject* parent)
    : QObject(parent),
      m_server(QSettings().value(kServerKey).toString()),
      m_station(QSettings().value(kStationKey).toString())
{
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &CentralSyncController::check);
}

void CentralSyncController::check()
{
    start(true);
}

CentralSyncController::~CentralSyncController()
{
    m_worker.request_stop();
}

void CentralSyncController::setStorePath(const QString& path)
{
    if (path == m_storePath) return;
    m_storePath = path;
    m_state.waiting.reset();
    m_recordedSince = 0;
    syncNow();
}

void CentralSyncController::setServer(const QString& conninfo, const QString& station)
{
    if (conninfo == m_server && station == m_station) return;
    m_server = conninfo;
    m_station = station;
    QSettings().setValue(kServerKey, m_server);
    QSettings().setValue(kStationKey, m_station);
    m_state = {};
    m_recordedSince = 0;
    emit stateChanged();
    syncNow();
}

void CentralSyncController::sessionRecorded()
{
    ++m_recordedSince;
    if (m_state.waiting) emit stateChanged();
    syncNow();
}

void CentralSyncController::syncNow()
{
    start(false);
}

void CentralSyncController::start(bool look)
{
    if (m_state.running) {
        m_again = m_again || !look;
        return;
    }
    if (!configured() || m_storePath.isEmpty()) return;
    if (!QFileInfo::exists(m_storePath)) {
        m_state.waiting = 0;  // nothing recorded yet
        emit stateChanged();
        return;
    }
    m_retry.stop();
    m_state.running = true;
    m_state.checking = look;
    m_state.done = m_state.total = 0;
    emit stateChanged();
    if (m_worker.joinable()) m_worker.join();  // the last one is over: it said so
    m_worker = std::jthread([this, path = m_storePath.toStdString(), server = m_server.toStdString(),
                             station = m_station.toStdString()](std::stop_token stop) {
        Result result;
        try {
            core::storage::SessionStore local(path, core::storage::Database::Access::ReadOnly);
            core::storage::central::CentralStore central(server);
            const auto outcome = core::storage::central::syncToCentral(
                local, central, station, stop, [this](const core::storage::central::SyncProgress& p) {
                    QMetaObject::invokeMethod(
                        this,
                        [this, p] {
                            m_state.done = p.done;
                            m_state.total = p.total;
                            emit stateChanged();
                        },
                        Qt::QueuedConnection);
                });
            result.outcome = syncText(outcome);
            result.sent = outcome.sent;
            if (outcome.updated > 0)
                result.outcome += tr("; later verdicts or notes added to %1 of them").arg(outcome.updated);
            if (!outcome.refused.empty())
                result.error =
                    QString::fromStdString(outcome.refused.front()) +
                    (outcome.refused.size() > 1 ? tr(" (and %1 more)").arg(outcome.refused.size() - 1) : QString());
            result.waiting = core::storage::central::sessionsToSync(local, central);
        } catch (const core::storage::central::CentralUnreachable& e) {
            result.error = QString::fromStdString(e.what());
            result.unreachable = true;
        } catch (const std::exception& e) {
            result.error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, result] { finished(result); }, Qt::QueuedConnection);
    });
}

void CentralSyncController::finished(const Result& result)
{
    // A look, or a send asked for while another ran, that sent nothing
    // keeps the outcome that did: "synced 3 sessions" stays the answer to
    // the press that sent them, not "synced 0 sessions, 3 already there".
    const bool quiet = (m_state.checking || std::exchange(m_followUp, false)) && result.sent == 0;
    m_state.running = false;
    m_state.checking = false;
    m_state.lastAttempt = QDateTime::currentDateTime();
    m_state.lastError = result.error;
    m_state.unreachable = result.unreachable;
    if (!result.unreachable) m_state.lastReached = m_state.lastAttempt;
    if (!result.outcome.isEmpty() && !(quiet && !m_state.lastOutcome.isEmpty())) m_state.lastOutcome = result.outcome;
    if (result.waiting) {
        m_state.waiting = result.waiting;
        m_recordedSince = 0;
    } else if (m_state.waiting) {
        *m_state.waiting += m_recordedSince;  // still waiting, with those recorded since
        m_recordedSince = 0;
    }
    // Offline or refused: try again in a few minutes, so the station catches
    // up alone. All sent: look again in a minute, so "up to date" stays true.
    const bool behind = !result.error.isEmpty() || (m_state.waiting && *m_state.waiting > 0);
    m_retry.start(behind ? kRetryMinutes * 60 * 1000 : kCheckSeconds * 1000);
    emit stateChanged();
    if (std::exchange(m_again, false)) {
        syncNow();
        m_followUp = m_state.running;
    }
}

}  // namespace tactiscope::ui
