// One channel against another over the last seconds, where a mode calls for
// it: in palpation F_H against F_L, a straight line through the origin whose
// slope is Q if the method holds; the slope fitted through the origin (least
// squares over the points in view) is shown with its name. Pulled from a LiveBuffer
// on a 10 Hz timer (a shape, not a waveform: it needs no more); at most
// kMaxPoints points are drawn, evenly strided.
#pragma once

#include "core/LiveBuffer.h"
#include "core/RingBuffer.h"
#include "ui/common/DisplayUnits.h"

#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>

class QCustomPlot;
class QCPCurve;
class QCPItemText;

namespace tactiscope::ui {

class XYPlotWidget : public QWidget {
    Q_OBJECT

public:
    static constexpr std::size_t kMaxPoints = 4000;

    explicit XYPlotWidget(QWidget* parent = nullptr);
    ~XYPlotWidget() override;

    // Plots channel `y` of `buffer` against channel `x`; the fitted slope is
    // shown as "`slopeName` = …" (in y's unit per x's when they differ).
    void setSource(std::shared_ptr<const core::LiveBuffer> buffer, std::size_t x, std::size_t y,
                   const DisplayUnit& xUnit, const DisplayUnit& yUnit, double sampleRate_hz,
                   const QString& slopeName = QStringLiteral("slope"));
    void clearSource();
    void setWindowLength(double seconds);

    int drawnPointCount() const;
    std::pair<double, double> xRange() const;
    std::pair<double, double> yRange() const;
    // The slope through the origin of the points in view, in display units,
    // and the text shown; none before two points.
    std::optional<double> slope() const { return m_slope; }
    QString slopeText() const;

private:
    void refresh();

    QCustomPlot* m_plot = nullptr;
    QCPCurve* m_curve = nullptr;
    QCPItemText* m_slopeLabel = nullptr;
    QString m_slopeName, m_slopeUnit;
    std::optional<double> m_slope;
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
