// The hum a panel scan's detector read its cantilevers through
// (core/detector/HumRisk.h), judged from their health as a report or
// `record` gathered it: said beside a verdict that the hum may have made.
#pragma once

#include "core/report/SignalQuality.h"
#include "core/storage/SessionSource.h"

#include <optional>
#include <string>

namespace tactiscope::core::report {

// In words, for a session whose mode detects defects and whose
// cantilevers (by role; its strain channels where none has one) carry a
// hum the detector read without a notch at its frequency (the session's
// recorded notch counts where its mode analysed the filtered channels);
// none otherwise.
struct DetectorHum {
    std::string text;
    double mains_hz = 0.0;  // the hum's: the notch that takes it out
};
std::optional<DetectorHum> detectorHumNote(const std::vector<ChannelQuality>& channels,
                                           const storage::SessionSummary& session);

}  // namespace tactiscope::core::report
