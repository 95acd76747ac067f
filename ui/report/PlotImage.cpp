// PlotImage: QCustomPlot to PNG or SVG.
#include "ui/report/PlotImage.h"

#include <QFileInfo>
#include <QSvgGenerator>
#include <qcustomplot.h>

#include <stdexcept>

namespace tactiscope::ui {

void savePlotImage(QCustomPlot& plot, QSize size, const QString& path, const QString& title)
{
    bool saved = false;
    if (QFileInfo(path).suffix().compare(QLatin1String("svg"), Qt::CaseInsensitive) == 0) {
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(title);
        QCPPainter painter;
        saved = painter.begin(&svg);
        if (saved) {
            plot.toPainter(&painter, size.width(), size.height());
            saved = painter.end();
        }
    } else {
        saved = plot.savePng(path, size.width(), size.height(), 2.0);
    }
    if (!saved) throw std::runtime_error("cannot write " + path.toStdString());
}

}  // namespace tactiscope::ui
