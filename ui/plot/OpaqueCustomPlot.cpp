// OpaqueCustomPlot: the first paint buffer an opaque image.
#include "ui/plot/OpaqueCustomPlot.h"

namespace tactiscope::ui {
namespace {

// A paint buffer on an opaque QImage (the raster engine's own format for
// opaque images), filled with the plot's background where QCustomPlot
// would clear it to transparent.
class OpaqueImageBuffer : public QCPAbstractPaintBuffer {
public:
    OpaqueImageBuffer(const QSize& size, double devicePixelRatio)
        : QCPAbstractPaintBuffer(size, devicePixelRatio)
    {
        OpaqueImageBuffer::reallocateBuffer();
    }

    QCPPainter* startPainting() override { return new QCPPainter(&m_image); }
    void draw(QCPPainter* painter) const override
    {
        if (painter && painter->isActive()) painter->drawImage(0, 0, m_image);
    }
    void clear(const QColor&) override { m_image.fill(OpaqueCustomPlot::kBackground); }

protected:
    void reallocateBuffer() override
    {
        setInvalidated();
        m_image = QImage(mSize * mDevicePixelRatio, QImage::Format_RGB32);
        m_image.setDevicePixelRatio(mDevicePixelRatio);
    }

private:
    QImage m_image;
};

}  // namespace

OpaqueCustomPlot::OpaqueCustomPlot(QWidget* parent)
    : QCustomPlot(parent)
{
    // QCustomPlot keeps its buffers from replot to replot and makes one only
    // where none is (setupPaintBuffers): the first, under every other, is ours.
    auto buffer =
        QSharedPointer<QCPAbstractPaintBuffer>(new OpaqueImageBuffer(viewport().size(), mBufferDevicePixelRatio));
    if (mPaintBuffers.isEmpty())
        mPaintBuffers.append(buffer);
    else
        mPaintBuffers[0] = buffer;
    // The buffer is filled with the background and covers the widget: had
    // QCustomPlot fill the widget with it first, each paint would set every
    // pixel twice (a tenth of a 16 × 10 kHz frame).
    setBackground(Qt::NoBrush);
}

}  // namespace tactiscope::ui
