// StabilityWatch: live samples → stability monitor → capture when armed.
#include "ui/calibration/StabilityWatch.h"

#include <algorithm>

namespace tactiscope::ui {

StabilityWatch::StabilityWatch(QObject* parent)
    : QObject(parent)
{
    m_timer.setInterval(50);  // 20 updates a second: a calm indicator, no lag worth noticing
    connect(&m_timer, &QTimer::timeout, this, &StabilityWatch::poll);
}

void StabilityWatch::setInput(std::shared_ptr<const core::LiveBuffer> buffer, std::size_t channel)
{
    m_buffer = std::move(buffer);
    m_channel = channel;
    m_cursor = {m_buffer ? m_buffer->samplesWritten() : 0, 0};
    m_lastSample.invalidate();
    restart();
    if (m_buffer)
        m_timer.start();
    else
        m_timer.stop();
}

void StabilityWatch::setSettings(const core::calibration::StabilitySettings& settings)
{
    const bool armed = isArmed();
    m_capture = core::calibration::SettledCapture(settings);
    m_settings = settings;
    if (armed) m_capture.arm();  // new limits, the same wait: judged on fresh samples
    restart();
}

void StabilityWatch::arm()
{
    m_capture.arm();
    emit updated();
    // Samples still waiting in the buffer were measured before the load was
    // placed: a window of them would be the old load's.
    if (m_buffer) m_cursor.next = std::max(m_cursor.next, m_buffer->samplesWritten());
}

bool StabilityWatch::receiving() const
{
    return m_lastSample.isValid() && m_lastSample.elapsed() < 1000;
}

void StabilityWatch::restart()
{
    m_capture.restart();
    emit updated();
}

void StabilityWatch::poll()
{
    const std::uint64_t overrun = m_cursor.overrun;
    if (m_buffer->readNew(m_cursor, m_chunk) == 0) {
        emit updated();  // so "no signal" shows when the device stops
        return;
    }
    m_lastSample.start();
    // A window must be contiguous: samples the reader lost break it.
    if (m_cursor.overrun != overrun) m_capture.restart();
    const auto& values = m_chunk.values.at(m_channel);
    for (std::size_t i = 0; i < m_chunk.sampleCount(); ++i) m_capture.add(m_chunk.time_s[i], values[i]);
    // Judged once per poll (20 times a second), not per sample: a window
    // of a fast channel holds hundreds of samples, each judgement fits them all.
    if (const auto kept = m_capture.judge()) emit captured(*kept);
    emit updated();
}

}  // namespace tactiscope::ui
