// `tactiscope-cli sessions --db FILE list|show|export|delete …`: the session
// store from the command line. The contract is in issue 7.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runSessions(const QStringList& arguments);

}  // namespace tactiscope::cli
