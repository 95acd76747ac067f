// The command line's filter and math-channel options, read alike by
// `filter` (one CSV channel) and `record` (the live signal chain): --notch,
// --lowpass, --highpass, --order, --moving-average, and `record`'s
// --filter-channel and --math.
#pragma once

#include "core/dsp/FilterSettings.h"
#include "core/signal/SignalSetup.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::cli {

// --notch, --lowpass, --highpass, --order and --moving-average.
QList<QCommandLineOption> filterOptions();
// Those options as one channel's filter; empty when none is given. The
// reason, for settings that cannot be.
std::optional<QString> readFilterSettings(const QCommandLineParser& parser, core::dsp::FilterSettings& settings);

// `record`'s: the filter options, --filter-channel and --math.
QList<QCommandLineOption> signalOptions();
// The live signal setup they ask for: the filter on each channel named by
// --filter-channel (every channel of `channels` when none is named) and
// the math channels. The reason, for options that cannot be.
std::optional<QString> readSignalSetup(const QCommandLineParser& parser, const std::vector<std::string>& channels,
                                       core::signal::SignalSetup& setup);
// The same for each of several devices, named `devices`, whose channels
// are `channels[i]`: a filter option given as DEVICE=VALUE is that
// device's own, one without a device every device's; --filter-channel
// DEVICE/CHANNEL and --math "DEVICE/NAME[UNIT]=EXPR" go to that device (a
// math channel is over one device's channels: the devices' clocks
// differ); a device's filter with no --filter-channel of its filters its
// every channel, and --analyze-filtered holds for each device with a
// filter. The reason, for options that cannot be (a name without its
// device, a device not here, a device's channel named in another's math).
std::optional<QString> readSignalSetups(const QCommandLineParser& parser, const std::vector<std::string>& devices,
                                        const std::vector<std::vector<std::string>>& channels,
                                        std::vector<core::signal::SignalSetup>& setups);

}  // namespace tactiscope::cli
