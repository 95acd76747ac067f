// Store-and-forward from the GUI: when a central store is configured
// (Session ▸ Central store…), this station's finished and interrupted
// sessions are pushed to it in the background (CentralSync) at start, after
// each recording, on demand, and every few minutes while the server cannot
// be reached, so a station offline for days catches up by itself; while all
// is sent it looks again every minute, so what the status bar says about
// the server stays true. It keeps what the user sees: how many sessions
// wait, the last outcome and the last error. The server's address is kept in the settings without a password
// (libpq takes that from ~/.pgpass).
#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>
#include <thread>

namespace tactiscope::ui {

struct CentralSyncState {
    bool running = false;
    bool checking = false;       // the running one is the minute's look, not a send asked for
    int done = 0, total = 0;     // sessions looked at, while running
    std::optional<int> waiting;  // sessions not yet on the server; none until first counted
    QDateTime lastAttempt;       // local time
    QString lastOutcome;         // "synced 2 sessions (1,200,000 samples), 1 already there"
    QString lastError;           // empty when the last attempt went through
    bool unreachable = false;    // the last attempt did not reach the server (lastError says why)
    QDateTime lastReached;       // local time the server last answered
};

class CentralSyncController : public QObject {
    Q_OBJECT

public:
    explicit CentralSyncController(QObject* parent = nullptr);
    ~CentralSyncController() override;  // stops after the session being sent, and waits

    // The station's own store, whose sessions are sent.
    void setStorePath(const QString& path);
    // Where to send them (empty: nowhere) and as which station (empty: the
    // server role's name); kept in the settings. Starts a push when set.
    void setServer(const QString& conninfo, const QString& station);
    const QString& server() const { return m_server; }
    const QString& station() const { return m_station; }
    bool configured() const { return !m_server.isEmpty(); }

    void syncNow();          // unless one is running or none is configured
    void sessionRecorded();  // one more waits; it is sent at once
    const CentralSyncState& state() const { return m_state; }

    static constexpr int kRetryMinutes = 5;
    static constexpr int kCheckSeconds = 60;

signals:
    void stateChanged();

private:
    struct Result;
    void finished(const Result& result);
    void check();  // the timer's: a sync that shows as a look, not a send
    void start(bool look);

    QString m_storePath;
    QString m_server;
    QString m_station;
    CentralSyncState m_state;
    int m_recordedSince = 0;  // sessions recorded since `waiting` was counted
    bool m_again = false;     // asked for while one was running
    bool m_followUp = false;  // the running one is that
    QTimer m_retry;
    std::jthread m_worker;
};

}  // namespace tactiscope::ui
