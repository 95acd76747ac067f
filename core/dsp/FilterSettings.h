// What a channel's filter is, as the user sets it: a mains notch (50 or
// 60 Hz, with harmonics), a Butterworth high-pass and/or low-pass (both: a
// band-pass) of one order, a moving average, and whether it runs
// zero-phase (review only). A filter never changes stored samples: the
// same settings over the same samples give the same series again.
#pragma once

#include <optional>
#include <string>

namespace tactiscope::core::dsp {

struct FilterSettings {
    std::optional<double> notch_hz;     // the mains frequency: 50 or 60
    std::optional<double> highpass_hz;  // −3 dB cut-off
    std::optional<double> lowpass_hz;   // −3 dB cut-off
    int order = 4;                      // of each Butterworth filter, 2–8
    double movingAverage_s = 0.0;       // window length; 0: none
    bool zeroPhase = false;             // forward and backward (review only; a live filter is causal)

    bool empty() const { return !notch_hz && !highpass_hz && !lowpass_hz && movingAverage_s <= 0.0; }
    // "mains notch 50 Hz and harmonics, low-pass 20 Hz (Butterworth, order 4)";
    // "none" when empty.
    std::string text() const;

    friend bool operator==(const FilterSettings&, const FilterSettings&) = default;
};

// Why `settings` cannot filter a channel sampled at `sampleRate_hz`, in
// words for the user; none when they can.
std::optional<std::string> filterRefusal(const FilterSettings& settings, double sampleRate_hz);

}  // namespace tactiscope::core::dsp
