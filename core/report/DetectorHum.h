// The hum a panel scan's detector read its cantilevers through
// (core/detector/HumRisk.h), judged from their health as a report, `record`
// or `analyze` gathered it: said beside a verdict that the hum may have made.
#pragma once

#include "core/report/SignalQuality.h"
#include "core/storage/SessionSource.h"

#include <functional>
#include <optional>
#include <string>

namespace tactiscope::core::report {

struct DetectorHum {
    std::string text;
    double mains_hz = 0.0;  // the hum's: the notch that takes it out
};

// The notch (none: no notch) the detector read a cantilever through, by name.
using NotchOf = std::function<std::optional<double>(const std::string& channel)>;

// In words, when one of the `cantilevers` (among `channels`, by name)
// carries a hum the detector read without a notch at its frequency; none
// otherwise. A strain stored in SI is said in µε.
std::optional<DetectorHum> detectorHumNote(const std::vector<ChannelQuality>& channels,
                                           const std::vector<std::string>& cantilevers, double sampleRate_hz,
                                           const NotchOf& notchOf);

// The same for a session whose mode detects defects, read as its mode read
// it: its cantilevers by role (its strain channels where none has one),
// through its recorded notch where its mode analysed the filtered channels.
std::optional<DetectorHum> sessionDetectorHum(const std::vector<ChannelQuality>& channels,
                                              const storage::SessionSummary& session);

}  // namespace tactiscope::core::report
