// Notches at the mains frequency and its harmonics: the hum a strain
// bridge on a press line picks up at 50 or 60 Hz, with 150 Hz (and 100 Hz)
// from rectifiers and transformer saturation. Each notch is the classic
// second-order one: zeros on the unit circle at the hum, poles just inside
// at the same angle, so the response is flat away from it. Its −3 dB width
// sets how fast it settles (about 1 / (π·width) seconds) and how far the
// mains may wander (±0.1 Hz is still −26 dB at a 2 Hz width).
#pragma once

#include "core/dsp/Biquad.h"

#include <vector>

namespace tactiscope::core::dsp {

// The −3 dB width of each notch.
inline constexpr double kNotchWidth_hz = 2.0;
// Harmonics notched besides the fundamental: 2nd and 3rd (100/150 Hz at 50 Hz).
inline constexpr int kNotchedHarmonics = 3;

// The notches of `mains_hz` and its harmonics up to the 3rd that lie below
// 0.45 of the sample rate, each with unit gain at DC. Throws
// std::invalid_argument when even the fundamental does not.
std::vector<Biquad> mainsNotches(double mains_hz, double sampleRate_hz, double width_hz = kNotchWidth_hz);

// The frequencies those notches sit at.
std::vector<double> notchedFrequencies(double mains_hz, double sampleRate_hz);

}  // namespace tactiscope::core::dsp
