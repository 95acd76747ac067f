// `tactiscope-cli sync --db LOCAL --server CONNINFO [--station NAME]`:
// sends a station's finished and interrupted sessions that the central
// store lacks, and says in one line what it did.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runSync(const QStringList& arguments);

}  // namespace tactiscope::cli
