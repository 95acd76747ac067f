// LiveSpectrum: the dock, the chosen channel's history, the redraw.
#include "ui/signal/LiveSpectrum.h"

#include "devices/session/LiveSession.h"
#include "ui/common/NumberText.h"
#include "ui/live/LiveStation.h"
#include "ui/signal/SpectrumView.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>

#include <cmath>
#include <limits>

namespace tactiscope::ui {

LiveSpectrum::LiveSpectrum(LiveStation& station, QMainWindow* window)
    : QObject(window),
      m_station(station),
      m_dock(new QDockWidget(tr("Spectrum"), window)),
      m_view(new SpectrumView(m_dock))
{
    m_dock->setObjectName(QStringLiteral("spectrumDock"));
    m_dock->setWidget(m_view);
    window->addDockWidget(Qt::LeftDockWidgetArea, m_dock);
    m_dock->hide();  // on request (View menu), a tab beside the device panel
    connect(&station, &LiveStation::connected, this, &LiveSpectrum::bind);
    connect(&station, &LiveStation::disconnecting, this, [this] {
        m_buffer.reset();
        m_view->setChannels({});
        m_view->clear(tr("No device."));
    });
    connect(&station, &LiveStation::polled, this, &LiveSpectrum::update);
    connect(m_view, &SpectrumView::settingsChanged, this, [this] {
        m_buffer.reset();  // another channel: its history afresh
        update();
    });
    connect(m_dock->toggleViewAction(), &QAction::triggered, this, [this](bool on) {
        if (on) m_dock->raise();  // its tab to the front
    });
    connect(m_dock, &QDockWidget::visibilityChanged, this, [this](bool shown) {
        if (shown) bind();
    });
}

// The device's channels, then its filtered and math channels.
void LiveSpectrum::bind()
{
    const auto* live = m_station.device();
    if (!live) return;
    auto channels = live->channels();
    const auto chain = live->signalChain();
    m_chainSeen = chain;
    if (chain) channels.insert(channels.end(), chain->outputs().begin(), chain->outputs().end());
    m_view->setChannels(channels);
    m_buffer.reset();
    update();
}

void LiveSpectrum::update()
{
    const auto* live = m_station.device();
    if (!live || !m_dock->isVisible()) return;
    const int chosen = m_view->channel();
    if (chosen < 0) return;
    const auto device = static_cast<std::size_t>(chosen);
    const auto chain = live->signalChain();
    if (chain != m_chainSeen.lock()) return bind();  // other filters or math channels: another list
    const std::size_t own = live->channels().size();
    if (!m_buffer) {
        if (device < own) {
            m_buffer = live->buffer();
            m_column = device;
        } else if (chain && device - own < chain->outputs().size()) {
            m_buffer = chain->output();
            m_column = device - own;
        } else {
            return;
        }
        m_rate_hz = live->source().nominalSampleRate_hz();
        m_cursor = {};
        m_history.clear();
        m_lastTime_s = std::numeric_limits<double>::quiet_NaN();
    }
    m_buffer->readNew(m_cursor, m_chunk);
    for (std::size_t i = 0; i < m_chunk.sampleCount() && m_column < m_chunk.values.size(); ++i) {
        // Samples the device lost leave a jump in time: the series breaks there.
        if (std::isfinite(m_lastTime_s) && m_chunk.time_s[i] - m_lastTime_s > 1.5 / m_rate_hz)
            m_history.push(std::numeric_limits<double>::quiet_NaN());
        m_lastTime_s = m_chunk.time_s[i];
        m_history.push(m_chunk.values[m_column][i]);
    }
    std::vector<double> values(m_history.size());
    m_history.copy(m_history.oldestIndex(), values);
    m_view->show(values, m_rate_hz,
                 tr("the last %1 s").arg(significantText(static_cast<double>(values.size()) / m_rate_hz, 3)));
}

}  // namespace tactiscope::ui
