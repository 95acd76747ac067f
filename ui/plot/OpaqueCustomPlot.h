// OpaqueCustomPlot is a QCustomPlot whose first paint buffer is an opaque
// QImage, filled with the plot's background, instead of a transparent
// QPixmap.
//
// Why: QCustomPlot paints its layers into a buffer cleared to transparent
// and composes it onto the widget with alpha blending on every paint; an
// opaque buffer is copied. And a QImage, unlike a QPixmap, can be written
// to directly: PixelColumnGraph fills a live trace's pixels itself, which
// is most of a 16 × 10 kHz frame when left to the raster engine (perf).
// The buffer is right while the layers drawn into it are all there is
// under it, which holds: it is filled with the background, white, and the
// widget's own background brush is none (QCustomPlot's toPixmap and
// savePng, which draw without the buffer, give a transparent background).
// Layers put in a buffer of their own (QCPLayer::lmBuffered) keep
// QCustomPlot's transparent buffers and are composed over it as before.
#pragma once

#include <qcustomplot.h>

namespace tactiscope::ui {

class OpaqueCustomPlot : public QCustomPlot {
    Q_OBJECT

public:
    explicit OpaqueCustomPlot(QWidget* parent = nullptr);

    // What the opaque buffer is filled with before each replot.
    static constexpr QRgb kBackground = 0xffffffff;
};

}  // namespace tactiscope::ui
