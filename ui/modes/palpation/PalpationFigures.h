// A palpation session's presses and sites as the clinician saw them live,
// for the review window and the report: their table rows, the phantom's grid map (each cell the mean
// k_o of its presses, in the stiffness colour map) as rich text, and the
// tissue scale with each site's mean marked, as a widget or an image.
#pragma once

#include "core/report/PressTable.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>

#include <vector>

namespace tactiscope::ui {

class StiffnessScale;

// A press's row as plain text: time (s), site, k_o ± SE (N/m), depth range (mm).
QStringList pressCells(const core::report::PressRow& press);
// The sites' rows as plain text: site, n, mean, SD, range (N/m). The
// columns share their decimals, those of the coarsest SD; a range whose
// ends read the same is the one value.
std::vector<QStringList> siteRows(const std::vector<core::report::SiteSummary>& sites);

// An HTML table of the grid's cells; empty when no site is a grid cell.
QString siteGridHtml(const std::vector<core::report::SiteSummary>& sites);
// Marks each site's mean on the scale.
void markSites(StiffnessScale& scale, const std::vector<core::report::SiteSummary>& sites);
// The tissue scale with the sites marked; `size` in logical pixels.
QImage renderTissueScale(const std::vector<core::report::SiteSummary>& sites, QSize size, double scale);

}  // namespace tactiscope::ui
