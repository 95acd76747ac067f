// `tactiscope-cli shunt-check --port PATH --channel NAME …`: switches the
// probe's shunt across a strain channel's bridge, compares the step with
// what the shunt, the gauge and the bridge say it must be, prints one line
// (PASS or FAIL with the deviation) and, with --db, keeps the result in the
// store's calibration history. Exit 0 passed, 1 failed or the probe cannot
// switch a shunt, 2 bad arguments.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runShuntCheck(const QStringList& arguments);

}  // namespace tactiscope::cli
