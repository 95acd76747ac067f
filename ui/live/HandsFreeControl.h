// The main window's hands-free part: Session ▸ Trigger…, Disarm trigger,
// Limits… and Sound on alarms; after each poll of the live station, the
// alarms raised and cleared (logged, told in the status bar, shown in the
// banner) and the trigger's state. The sessions the trigger cuts end
// through the station like any recording (its recordingEnded, marked
// triggered: no verdict is asked, the line goes on). The rules are the
// live pipeline's (core/trigger below it); this only asks and shows.
#pragma once

#include "core/storage/SessionSource.h"
#include "core/trigger/TriggerMachine.h"
#include "devices/session/LivePipeline.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <optional>

class QAction;
class QMenu;
class QWidget;

namespace tactiscope::ui {

class LimitsDialog;
class LiveStation;
class TriggerDialog;
class WatchBanner;
struct Problem;

class HandsFreeControl : public QObject {
    Q_OBJECT

public:
    struct Hooks {
        std::function<core::storage::SessionMetadata()> metadata;  // the session bar's
        // Why the site's policy refuses to record with that metadata; empty when it does not.
        std::function<QString(const core::storage::SessionMetadata&)> refusal;
        std::function<void(const Problem&)> problem;
        std::function<void(const QString&)> tell;  // a line in the status bar
    };
    HandsFreeControl(LiveStation& station, WatchBanner* banner, Hooks hooks, QWidget* window);

    void addActions(QMenu* session);
    TriggerDialog* showTrigger();
    LimitsDialog* showLimits();
    // Arms the trigger with the session bar's metadata; false (and the
    // problem shown) when the station or the policy refuses.
    bool arm(const core::trigger::TriggerSettings& settings);
    bool armed() const;
    void disarm();  // an open triggered session ends as complete

private:
    void update(const devices::session::PipelineNews& news);
    void showAlarms(const devices::session::PipelineNews& news);
    void showTriggerState(const devices::session::LiveSession& live);
    void disconnected();

    LiveStation& m_station;
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
