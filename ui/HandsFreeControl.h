// The main window's hands-free part: Session ▸ Trigger…, Disarm trigger,
// Limits… and Sound on alarms; after each poll of the live session, the
// sessions the trigger ended (handed to the window like a stopped
// recording, without asking a verdict: the line goes on), the alarms
// raised and cleared (logged, told in the status bar, shown in the banner),
// and the trigger's state. The rules are the live session's (core/trigger
// below it); this only asks and shows.
#pragma once

#include "core/storage/SessionSource.h"
#include "core/trigger/TriggerMachine.h"
#include "devices/session/LiveRecords.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

class QAction;
class QMenu;
class QWidget;

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class LimitsDialog;
class TriggerDialog;
class WatchBanner;
struct Problem;

class HandsFreeControl : public QObject {
    Q_OBJECT

public:
    struct Hooks {
        std::function<devices::session::LiveSession*()> session;   // null when no device is connected
        std::function<core::storage::SessionMetadata()> metadata;  // the session bar's
        // Why the site's policy refuses to record with that metadata; empty when it does not.
        std::function<QString(const core::storage::SessionMetadata&)> refusal;
        std::function<void(const devices::session::RecordingSummary&)> sessionEnded;
        std::function<void(const Problem&)> problem;
        std::function<void(const QString&)> tell;  // a line in the status bar
        std::function<void()> stateChanged;        // armed or disarmed: the record button follows
    };
    HandsFreeControl(WatchBanner* banner, Hooks hooks, QWidget* window);

    void addActions(QMenu* session);
    TriggerDialog* showTrigger();
    LimitsDialog* showLimits();
    // Arms the trigger with the session bar's metadata; false (and the
    // problem shown) when the session or the policy refuses.
    bool arm(const core::trigger::TriggerSettings& settings);
    bool armed() const;
    void disarm();  // an open triggered session ends as complete
    void update();  // after each poll
    void disconnected();

private:
    Hooks m_hooks;
    WatchBanner* m_banner;
    QWidget* m_window;
    QPointer<TriggerDialog> m_triggerDialog;
    QPointer<LimitsDialog> m_limitsDialog;
    std::optional<core::trigger::TriggerSettings> m_last;  // the last armed, offered again
    QAction* m_disarm = nullptr;
    QAction* m_sound = nullptr;
};

}  // namespace tactiscope::ui
