// The health subcommand: each channel's mains hum, noise floor, drift and
// clipped samples, of a CSV file or a stored session.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runHealth(const QStringList& arguments);

}  // namespace tactiscope::cli
