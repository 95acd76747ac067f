// The filter subcommand: a CSV file written again with one channel
// filtered (mains notch, Butterworth high/low/band-pass, moving average),
// every other column as it was.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runFilter(const QStringList& arguments);

}  // namespace tactiscope::cli
