// Mains hum in a channel: a line at 50 or 60 Hz (within ±1.5 Hz: a grid
// wanders by tenths) standing 20 dB above the spectrum's median, read from
// the flat-top amplitude spectrum, so its level is the hum's amplitude in
// the channel's own unit (µε, mN, pF), not only a ratio in dB. Which of
// the two it is tells the site's mains frequency, for the notch.
#pragma once

#include "core/dsp/WelchSpectrum.h"

#include <optional>

namespace tactiscope::core::dsp {

struct MainsHum {
    double mains_hz = 0.0;   // 50 or 60
    double line_hz = 0.0;    // where the line is
    double amplitude = 0.0;  // of the fundamental, in the channel's unit
};

std::optional<MainsHum> findMainsHum(const Spectrum& spectrum);

// The noise floor: the median amplitude spectral density (unit/√Hz) from
// 1 Hz (and five bins) up to 0.45 of the sample rate; lines barely move a
// median. NaN for an empty spectrum.
double noiseFloor(const Spectrum& spectrum);

}  // namespace tactiscope::core::dsp
