// Watches one live channel for a calibration step: new samples go into a
// core SettledCapture, whose window is judged each time samples arrive
// (20 times a second), so the wizard can show whether the signal has
// settled and, once armed, take a reading by the capture's rule: of
// samples wholly after the moment it was armed (after the load was
// placed), a stable window, then a fresh stable window after it, which is
// the one kept (the first still holds the tail of the swing).
#pragma once

#include "core/LiveBuffer.h"
#include "core/calibration/SettledCapture.h"

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
    void disarm() { m_capture.disarm(); }
    bool isArmed() const { return m_capture.phase() != core::calibration::SettledCapture::Phase::Watching; }
    // Armed and stable once: the window being filled is the one kept.
    bool isAveraging() const { return m_capture.phase() == core::calibration::SettledCapture::Phase::Averaging; }

    // The statistics of the newest full window; none while one fills.
    const std::optional<core::calibration::WindowStatistics>& latest() const { return m_capture.latest(); }
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
    core::calibration::SettledCapture m_capture{m_settings};
    QTimer m_timer;
    QElapsedTimer m_lastSample;
};

}  // namespace tactiscope::ui
