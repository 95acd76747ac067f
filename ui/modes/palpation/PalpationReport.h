// A palpation session's section of the report (seed 001): the presses with
// their stiffness and uncertainty, each site summed up, the phantom's grid
// map and the tissue scale with each site's mean, as the clinician saw them
// live.
#pragma once

#include "core/report/ReportData.h"

#include <QString>

class QTextDocument;

namespace tactiscope::ui {

// The section's HTML; the scale's image is added to `document`. Empty for
// a session without presses.
QString palpationReportSection(const core::report::ReportData& data, QTextDocument& document);

}  // namespace tactiscope::ui
