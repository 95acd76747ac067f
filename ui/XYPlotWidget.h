// One channel against another over the last seconds, where a mode calls for
// it: in palpation F_H against F_L (a straight line through the origin whose
// slope is Q, if the method holds), in the capacitive mode the force against
// the tip deflection (slope: the beam's stiffness). Pulled from a LiveBuffer
// on a 10 Hz timer (a shape, not a waveform: it needs no more); at most
// kMaxPoints points are drawn, evenly strided.
#pragma once

#include "core/LiveBuffer.h"
#include "core/RingBuffer.h"
#include "ui/DisplayUnits.h"

#include <QTimer>
#include <QWidget>

#include <memory>

class QCustomPlot;
class QCPCurve;

namespace tactiscope::ui {

class XYPlotWidget : public QWidget {
    Q_OBJECT

public:
    static constexpr std::size_t kMaxPoints = 4000;

    explicit XYPlotWidget(QWidget* parent = nullptr);
    ~XYPlotWidget() override;

    // Plots channel `y` of `buffer` against channel `x`.
    void setSource(std::shared_ptr<const core::LiveBuffer> buffer, std::size_t x, std::size_t y,
                   const DisplayUnit& xUnit, const DisplayUnit& yUnit, double sampleRate_hz);
    void clearSource();
    void setWindowLength(double seconds);

    int drawnPointCount() const;
    std::pair<double, double> xRange() const;
    std::pair<double, double> yRange() const;

private:
    void refresh();

    QCustomPlot* m_plot = nullptr;
    QCPCurve* m_curve = nullptr;
    QTimer m_timer;
    std::shared_ptr<const core::LiveBuffer> m_buffer;
    core::LiveCursor m_cursor;
    core::LiveChunk m_chunk;
    std::size_t m_x = 0, m_y = 0;
    double m_xScale = 1.0, m_yScale = 1.0;
    double m_rate_hz = 0.0;
    double m_window_s = 10.0;
    std::unique_ptr<core::RingBuffer<double>> m_xs, m_ys;
};

}  // namespace tactiscope::ui
