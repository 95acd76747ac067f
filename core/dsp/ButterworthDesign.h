// Butterworth low- and high-pass filters as second-order sections,
// designed by liquid-dsp (liquid_iirdes: analog prototype, pre-warped
// bilinear transform, sections), the field's well-kept design code. The
// sections it gives in single precision are carried into double, where
// the cascade runs; tests hold the result to the analytic response.
#pragma once

#include "core/dsp/Biquad.h"

#include <vector>

namespace tactiscope::core::dsp {

enum class PassBand { Low, High };

inline constexpr int kLeastButterworthOrder = 2;
inline constexpr int kMostButterworthOrder = 8;

// `order` (2–8) sections' worth of a Butterworth filter, −3 dB at
// `cutoff_hz` for `sampleRate_hz`. Throws std::invalid_argument for an
// order or a cut-off outside (0, 0.45 of the sample rate).
std::vector<Biquad> butterworth(PassBand band, int order, double cutoff_hz, double sampleRate_hz);

}  // namespace tactiscope::core::dsp
