// `tactiscope-cli record --port PATH … --db FILE`: records a probe into the
// session store until --seconds have passed or Ctrl-C, then prints a
// one-line summary with the session id. The contract is in issue 6.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runRecord(const QStringList& arguments);

}  // namespace tactiscope::cli
