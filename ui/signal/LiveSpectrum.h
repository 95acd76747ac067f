// View ▸ Spectrum, live: the spectrum of one of the window's device's
// channels, or of a filtered or math channel, over its last 8,192 samples,
// drawn again at each poll of the live station while the dock is shown.
// A jump in the samples' times (samples the device lost) breaks the
// series there, so no segment spans it.
#pragma once

#include "core/LiveBuffer.h"
#include "core/RingBuffer.h"
#include "core/signal/SignalChain.h"

#include <QObject>

#include <memory>

class QDockWidget;
class QMainWindow;

namespace tactiscope::ui {

class LiveStation;
class SpectrumView;

class LiveSpectrum : public QObject {
    Q_OBJECT

public:
    static constexpr std::size_t kPoints = 8192;

    LiveSpectrum(LiveStation& station, QMainWindow* window);
    QDockWidget* dock() const { return m_dock; }
    SpectrumView* view() const { return m_view; }

private:
    void bind();    // the channels to choose from, the history afresh
    void update();  // new samples in, the spectrum drawn

    LiveStation& m_station;
    QDockWidget* m_dock;
    SpectrumView* m_view;
    std::shared_ptr<const core::LiveBuffer> m_buffer;            // the device's, or its chain's
    std::weak_ptr<const core::signal::SignalChain> m_chainSeen;  // whose outputs the list offers
    std::size_t m_column = 0;                                    // the chosen channel in it
    double m_rate_hz = 0.0;
    core::LiveCursor m_cursor;
    core::LiveChunk m_chunk;
    core::RingBuffer<double> m_history{kPoints};
    double m_lastTime_s = 0.0;
};

}  // namespace tactiscope::ui
