// Mains hum the detector would be blinded by, said where it reads its
// cantilevers: a common hum correlates the gauges at every lag that is a
// multiple of its period, so from about four times the gauges' noise
// crossings are lost, from ten times every one (docs/detector.md, "Under
// mains hum"). Judged on the cantilevers' health as the detector read them
// (before any notch): a hum of twice their noise or more, unless a notch at
// its frequency took it out; a notch at the other mains frequency is no
// notch for it.
#pragma once

#include "core/dsp/SignalHealth.h"

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

// How much of a recording is judged: enough for the hum's line to stand
// out (a tenth of a hertz), little enough to be read at once at the end.
inline constexpr double kHumJudged_s = 20.0;

struct HumRisk {
    std::string channel;     // the cantilever whose hum stands highest over its noise
    double mains_hz = 0.0;   // 50 or 60
    double amplitude = 0.0;  // of the fundamental, in the channel's unit
    double noise = 0.0;      // its white-noise σ from its floor, in the same unit
};

// The worst hum among `channels` (names) and their `health`, sampled at
// `sampleRate_hz`, that the detector read through `notch_hz` (none: no
// notch); none when there is no risk.
std::optional<HumRisk> detectorHumRisk(const std::vector<std::string>& channels,
                                       const std::vector<dsp::ChannelHealth>& health, double sampleRate_hz,
                                       std::optional<double> notch_hz);

// "a carries 25 µε of 50 Hz hum, 50 times its noise: the detector read it
// without a notch and loses crossings under such a hum (docs/detector.md,
// "Under mains hum")"; the amount in `unit` at `scale` per channel unit,
// left out when `unit` is empty.
std::string humRiskText(const HumRisk& risk, std::optional<double> notch_hz, double scale, const std::string& unit);

}  // namespace tactiscope::core::detector
