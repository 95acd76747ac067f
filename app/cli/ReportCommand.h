// `tactiscope-cli report --db FILE --session ID|last --output REPORT.pdf
// [--from S] [--to S]`: a session's inspection report as a PDF, the same
// document the GUI exports. Bad input ends with exit 2 and one line on
// stderr. The contract is in issue 9.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runReport(const QStringList& arguments);

// The report paints text and plots, so it needs a GUI application object
// (on the offscreen platform: no display).
bool commandNeedsPainting(const char* command);

}  // namespace tactiscope::cli
