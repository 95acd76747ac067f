// The main window's status bar fields: the device's name on the left; on
// the right the link (state, rate, losses; red when unhealthy) and the
// recording (session, samples written and lost while recording, red; the
// saved session afterwards, still with its losses: a loss is never hidden).
#pragma once

#include <QObject>
#include <QString>

#include <cstdint>

class QLabel;
class QStatusBar;

namespace tactiscope::core::storage {
struct RecorderStats;
}

namespace tactiscope::ui {

struct LinkCounters;

class StatusLine : public QObject {
    Q_OBJECT

public:
    explicit StatusLine(QStatusBar* bar);

    void setDevice(const QString& name);  // empty: no device
    void setLink(const QString& state);   // "Connecting…", "Connection failed", or empty
    void showLink(const LinkCounters& counters);
    void showRecording(std::int64_t session, const core::storage::RecorderStats& stats);
    void showSaved(std::int64_t session, const core::storage::RecorderStats& stats);

private:
    QLabel* m_device;
    QLabel* m_link;
    QLabel* m_recording;
};

}  // namespace tactiscope::ui
