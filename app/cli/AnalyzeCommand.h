// `tactiscope-cli analyze --db FILE --session ID|last [detector options as
// in detect] [--json]`: the surface-deflection detector re-run on a stored
// panel-scan session. The contract is in issue 7.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runAnalyze(const QStringList& arguments);

}  // namespace tactiscope::cli
