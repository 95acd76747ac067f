// What a capacitive session's readings went through, as a name–value table
// for the report and the review window alike: the baselines C0, the
// sensitivity used, and the calibration record with its fit (sensitivity ±
// SE, R², points, detection limit, baseline noise and drift, date and who),
// or the beam model when none was recorded.
#pragma once

#include "core/report/ReportData.h"

#include <QString>

namespace tactiscope::ui {

QString capacitiveBasisHtml(const core::report::CapacitiveBasis& basis);
// The report's section of a capacitive session: the basis under a heading;
// empty when the report has none.
QString capacitiveReportSection(const core::report::ReportData& data);

}  // namespace tactiscope::ui
