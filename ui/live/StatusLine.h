// The main window's status bar fields: the device's name on the left; on
// the right the link (state, rate, losses; red when unhealthy) and the
// recording (session, samples written and lost while recording, red; the
// saved session afterwards, still with its losses: a loss is never hidden).
// It follows the live station (watch()): the device connecting, connected
// or failed, each poll's counters, and what the links noticed (logged and
// told in the bar).
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
class LiveStation;

class StatusLine : public QObject {
    Q_OBJECT

public:
    explicit StatusLine(QStatusBar* bar);

    // Shows what `station` says from now on.
    void watch(LiveStation& station);

    void setDevice(const QString& name);  // empty: no device
    void setLink(const QString& state);   // "Connecting…", "Connection failed", or empty
    void showLink(const LinkCounters& counters);
    void showRecording(std::int64_t session, const core::storage::RecorderStats& stats);
    void showSaved(std::int64_t session, const core::storage::RecorderStats& stats);

private:
    QStatusBar* m_bar;
    QLabel* m_device;
    QLabel* m_link;
    QLabel* m_recording;
};

}  // namespace tactiscope::ui
