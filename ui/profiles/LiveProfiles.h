// The sensor-profile dialog (Session ▸ Sensor profiles…, non-modal, one)
// on the live station: a profile made active is used by the window's
// device at once (its mode's processor reads through it), except while
// recording, when the dialog is locked: a session keeps one sensor, so its
// readings and its stored profile agree.
#pragma once

#include "core/Vocabulary.h"

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace tactiscope::ui {

class LiveStation;
class SensorProfileDialog;

class LiveProfiles : public QObject {
    Q_OBJECT

public:
    struct Hooks {
        std::function<core::Mode()> mode;          // the dialog opens on it
        std::function<void(core::Mode)> applied;   // the mode's views read the new probe
        std::function<void(const QString&)> tell;  // a line in the status bar
    };
    LiveProfiles(LiveStation& station, Hooks hooks, QWidget* window);

    SensorProfileDialog* show();

private:
    void apply(const QString& modeName);
    void lock();

    LiveStation& m_station;
    Hooks m_hooks;
    QWidget* m_window;
    SensorProfileDialog* m_dialog = nullptr;  // made when first asked for
};

}  // namespace tactiscope::ui
