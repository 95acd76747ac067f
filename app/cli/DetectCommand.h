// `tactiscope-cli detect`: the surface-deflection detector (seed 000) over a
// CSV recording, with per-sample output, events and timing. The options and
// output columns are a contract other tools rely on; see the usage text.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runDetect(const QStringList& arguments);

}  // namespace tactiscope::cli
