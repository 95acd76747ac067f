// Watches one live channel for a calibration step: new samples go into a
// core StabilityMonitor, whose window is judged each time samples arrive
// (20 times a second), so the wizard can show whether the signal has
// settled and, once armed, take the first window found stable that lies
// wholly after the moment it was armed (after the load was placed), never
// one that still holds the swing of the previous load.
#pragma once

#include "core/LiveBuffer.h"
#include "core/calibration/StabilityMonitor.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>

namespace tactiscope::ui {

class StabilityWatch : public QObject {
    Q_OBJECT

public:
    explicit StabilityWatch(QObject* parent = nullptr);

    // Reads `channel` of `buffer` from the newest sample on.
    void setInput(std::shared_ptr<const core::LiveBuffer> buffer, std::size_t channel);
    // Starts the window over. Throws std::invalid_argument for bad settings.
    void setSettings(const core::calibration::StabilitySettings& settings);
    const core::calibration::StabilitySettings& settings() const { return m_settings; }

    // The next stable window of samples that arrive after this call is
    // captured (once); samples not yet read are skipped.
    void arm();
    void disarm() { m_armed = false; }
    bool isArmed() const { return m_armed; }

    // The statistics of the newest full window; none while one fills.
    const std::optional<core::calibration::WindowStatistics>& latest() const { return m_latest; }
    // Whether samples arrived within the last second.
    bool receiving() const;

signals:
    void updated();
    void captured(const core::calibration::WindowStatistics& window);

private:
    void poll();
    void restart();

    std::shared_ptr<const core::LiveBuffer> m_buffer;
    std::size_t m_channel = 0;
    core::LiveCursor m_cursor;
    core::LiveChunk m_chunk;
    core::calibration::StabilitySettings m_settings{1.0, 0.0, 0.0};
    core::calibration::StabilityMonitor m_monitor{m_settings};
    std::optional<core::calibration::WindowStatistics> m_latest;
    bool m_armed = false;
    QTimer m_timer;
    QElapsedTimer m_lastSample;
};

}  // namespace tactiscope::ui
