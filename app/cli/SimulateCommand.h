// `tactiscope-cli simulate`: runs a simulator scenario as fast as possible and
// writes it as CSV (header `t` then the channel names; t in seconds, values
// in SI units), e.g. test input for the detector.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runSimulate(const QStringList& arguments);

}  // namespace tactiscope::cli
