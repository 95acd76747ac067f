// CentralSyncController: one push at a time on a worker thread; results
// come back to the GUI thread queued on this object.
#include "ui/central/CentralSyncController.h"

#include "core/storage/central/CentralSync.h"

#include <QFileInfo>
#include <QMetaObject>
#include <QSettings>

#include <utility>

namespace tactiscope::ui {

namespace {
const QString kServerKey = QStringLiteral("central/server");
const QString kStationKey = QStringLiteral("central/station");
}  // namespace

struct CentralSyncController::Result {
    QString outcome;
    QString error;
    std::optional<int> waiting;
};

CentralSyncController::CentralSyncController(QObject* parent)
    : QObject(parent),
      m_server(QSettings().value(kServerKey).toString()),
      m_station(QSettings().value(kStationKey).toString())
{
    m_retry.setSingleShot(true);
    m_retry.setInterval(kRetryMinutes * 60 * 1000);
    connect(&m_retry, &QTimer::timeout, this, &CentralSyncController::syncNow);
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
    if (m_state.running) {
        m_again = true;
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
            result.outcome = QString::fromStdString(core::storage::central::syncSummary(outcome));
            if (outcome.updated > 0)
                result.outcome += tr("; later verdicts or notes added to %n of them", nullptr, outcome.updated);
            if (!outcome.refused.empty())
                result.error =
                    QString::fromStdString(outcome.refused.front()) +
                    (outcome.refused.size() > 1 ? tr(" (and %1 more)").arg(outcome.refused.size() - 1) : QString());
            result.waiting = core::storage::central::sessionsToSync(local, central);
        } catch (const std::exception& e) {
            result.error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, result] { finished(result); }, Qt::QueuedConnection);
    });
}

void CentralSyncController::finished(const Result& result)
{
    m_state.running = false;
    m_state.lastAttempt = QDateTime::currentDateTime();
    m_state.lastError = result.error;
    if (!result.outcome.isEmpty()) m_state.lastOutcome = result.outcome;
    if (result.waiting) {
        m_state.waiting = result.waiting;
        m_recordedSince = 0;
    } else if (m_state.waiting) {
        *m_state.waiting += m_recordedSince;  // still waiting, with those recorded since
        m_recordedSince = 0;
    }
    // Offline or refused: try again later, so the station catches up alone.
    if (!result.error.isEmpty() || (m_state.waiting && *m_state.waiting > 0)) m_retry.start();
    emit stateChanged();
    if (std::exchange(m_again, false)) syncNow();
}

}  // namespace tactiscope::ui
