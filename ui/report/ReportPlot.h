// The key plot of an inspection report: each channel of the session over
// the report's range as its min/max band (from the store's overview, so an
// hour-long session costs no more than a minute), one lane per channel on a
// shared time axis, with the defects, presses and markers drawn over them
// and the lost stretches greyed. Rendered off screen to an image for the
// PDF, and to PNG or SVG files.
#pragma once

#include "core/report/ReportData.h"

#include <QImage>
#include <QSize>
#include <QString>

namespace tactiscope::ui {

// `size` in logical pixels; the image has scale × as many.
QImage renderReportPlot(const core::report::ReportData& data, QSize size, double scale);
// PNG (raster, at scale 2) or SVG (vector) by the file's suffix. Throws
// std::runtime_error when the file cannot be written.
void saveReportPlot(const core::report::ReportData& data, QSize size, const QString& path);

}  // namespace tactiscope::ui
