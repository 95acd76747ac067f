// A plot saved as a picture: PNG (raster, twice the logical size for sharp
// print) or SVG (vector), by the file's suffix. Shared by the report plot
// and the review view's "save the current plot".
#pragma once

#include <QSize>
#include <QString>

class QCustomPlot;

namespace tactiscope::ui {

// Throws std::runtime_error when the file cannot be written.
void savePlotImage(QCustomPlot& plot, QSize size, const QString& path, const QString& title);

}  // namespace tactiscope::ui
