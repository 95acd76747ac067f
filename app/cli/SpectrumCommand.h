// The spectrum subcommand: Welch's power spectral density of one channel
// of a CSV file or a stored session, and its strongest lines.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runSpectrum(const QStringList& arguments);

}  // namespace tactiscope::cli
