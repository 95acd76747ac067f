// The strip above the traces that says what the hands-free rules are
// doing: the trigger's state (armed and waiting for its condition,
// recording a triggered session, finished) and the limit alarms raised
// now, amber for a warning and red for a critical one, with an optional
// beep when one is raised. Hidden while there is nothing to say, so the
// traces keep their room.
#pragma once

#include "devices/session/TriggerGate.h"

#include <QWidget>

#include <optional>
#include <vector>

class QLabel;

namespace tactiscope::ui {

class WatchBanner : public QWidget {
    Q_OBJECT

public:
    explicit WatchBanner(QWidget* parent = nullptr);

    // The trigger armed (none: no trigger), its state and the session it
    // is on (the subject the next or current session takes).
    struct TriggerView {
        QString condition;  // as the operator reads it: "a > 20 µε"
        devices::session::TriggerStatus status;
        std::optional<unsigned> sessions;  // asked for; none: re-arming
        bool recording = false;            // a triggered session is being recorded
        QString subject;                   // of the session recorded or next
    };
    void showTrigger(const std::optional<TriggerView>& trigger);
    // The alarms raised now, in words (none: calm); `fresh`: one was
    // raised since the last call, which beeps when sound is on.
    struct AlarmLine {
        bool critical = false;
        QString text;  // "force above its critical limit 956 µN (978 µN)"
    };
    void showAlarms(const std::vector<AlarmLine>& raised, bool fresh);
    void setSoundOn(bool on) { m_sound = on; }
    bool soundOn() const { return m_sound; }

    QString triggerText() const;
    QString alarmText() const;

private:
    void updateVisibility();

    QLabel* m_trigger;
    QLabel* m_alarm;
    bool m_sound = false;
};

}  // namespace tactiscope::ui
