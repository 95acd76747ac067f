// The session bar across the top of the main window: what is being
// inspected (mode, subject, operator), the record button, the elapsed time
// and where the session is written. Large targets, readable at arm's length
// with gloves on; the fields lock while recording so a session's metadata
// cannot change halfway. It follows the live station (watch()): record
// enabled while a device streams, recording, armed, the elapsed time.
#pragma once

#include "core/storage/SessionStore.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tactiscope::ui {

class LiveStation;

class SessionBar : public QWidget {
    Q_OBJECT

public:
    explicit SessionBar(QWidget* parent = nullptr);

    void watch(const LiveStation& station);

    // Mode, subject and operator as typed (trimmed).
    core::storage::SessionMetadata metadata() const;
    void setMetadata(const core::storage::SessionMetadata& metadata);
    void setMode(core::Mode mode);

    void setRecordEnabled(bool enabled);  // a device is streaming
    void setRecording(bool recording);
    // A trigger is armed: the button disarms it, the fields hold (its
    // sessions take them), whether or not one is recording now.
    void setArmed(bool armed);
    void setElapsed(double seconds);
    void setStorePath(const QString& path);

signals:
    void recordClicked();  // start or stop, by the button
    void modeChanged();

private:
    QComboBox* m_mode = nullptr;
    QLineEdit* m_subject = nullptr;
    QLineEdit* m_operator = nullptr;
    QPushButton* m_record = nullptr;
    QLabel* m_elapsed = nullptr;
    QLabel* m_store = nullptr;
    bool m_recording = false;
    bool m_armed = false;
    void applyState();
};

}  // namespace tactiscope::ui
