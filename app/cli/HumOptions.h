// --hum and --hum-hz of simulate and emulate: mains hum added to the
// simulated probe's channels (devices/simulator/MainsHumOverlay.h), to see
// what the detector and the signal tools make of a press line's pick-up.
#pragma once

#include "devices/simulator/MainsHumOverlay.h"

#include <QCommandLineParser>
#include <QString>

#include <optional>

namespace tactiscope::cli {

void addHumOptions(QCommandLineParser& parser);
// The settings (no hum when --hum is not given); nothing, with the usage
// error in `error`, for a bad value.
std::optional<devices::simulator::MainsHumSettings> parseHumOptions(const QCommandLineParser& parser, QString& error);

}  // namespace tactiscope::cli
