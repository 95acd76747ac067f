// `tactiscope-cli model PROFILE.json`: what the sensor model says about a
// profile, as one JSON object (key names are a contract; see the usage).
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runModel(const QStringList& arguments);

}  // namespace tactiscope::cli
