// What a channel's filter is, as the user sets it and the session records
// it: a mains notch (50 or 60 Hz, with harmonics), a Butterworth high-pass
// and/or low-pass (both: a band-pass) of one order, a moving average, and
// for review whether it runs zero-phase. The stored samples never change;
// these settings, kept with the session (its provenance and its report),
// are what re-analysis applies to reproduce the filtered series.
#pragma once

#include <optional>
#include <string>
#include <vector>

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

// A channel's filter as a session records it.
struct ChannelFilterSetting {
    std::string channel;
    FilterSettings settings;

    friend bool operator==(const ChannelFilterSetting&, const ChannelFilterSetting&) = default;
};

// The JSON a session keeps: [{"channel": "a", "notch_hz": 50, "highpass_hz": null,
// "lowpass_hz": 20, "order": 4, "moving_average_s": 0, "zero_phase": false}, …].
std::string filtersJson(const std::vector<ChannelFilterSetting>& filters);
// Reads it back; throws std::invalid_argument naming what is wrong (a
// stored text is checked like any other input).
std::vector<ChannelFilterSetting> filtersFromJson(const std::string& json);

}  // namespace tactiscope::core::dsp
