// One channel's filter built from its settings at the channel's sample
// rate: mains notches, then the Butterworth high- and low-pass, then the
// moving average. Live it runs causally, a sample at a time; a missing
// sample (NaN: a gap, a lost sample) passes through as NaN and restarts
// the filter, as a filter cannot know what the gap held. Re-analysis runs
// the same code over the stored samples, so it gives the live series bit
// for bit. In review it may run zero-phase over each gap-free stretch.
#pragma once

#include "core/dsp/Biquad.h"
#include "core/dsp/FilterSettings.h"
#include "core/dsp/MovingAverage.h"

#include <span>
#include <vector>

namespace tactiscope::core::dsp {

class ChannelFilter {
public:
    // Throws std::invalid_argument with filterRefusal()'s words.
    ChannelFilter(const FilterSettings& settings, double sampleRate_hz);

    const FilterSettings& settings() const { return m_settings; }
    double sampleRate_hz() const { return m_sampleRate_hz; }

    double process(double x);
    void process(std::span<double> values);
    void reset();
    // Its sections' state (BiquadCascade::state()), and going on from one
    // with its moving average started afresh: where a recording begins.
    std::optional<std::vector<double>> sectionsState() const { return m_cascade.state(); }
    void startFrom(const std::optional<std::vector<double>>& sectionsState);

    // The whole chain's response at `frequency_hz` (causal).
    std::complex<double> response(double frequency_hz) const;
    // How far the causal output lags the input where the signal lives: the
    // group delay at the pass band's reference frequency (DC, or the middle
    // of a band-pass, or 4 × a high-pass's cut-off), in seconds. 0 for a
    // zero-phase filter.
    double delay_s() const;
    double delayFrequency_hz() const;

private:
    FilterSettings m_settings;
    double m_sampleRate_hz;
    BiquadCascade m_cascade;
    MovingAverage m_average;
    bool m_averaging = false;
};

// `values` (NaN where missing) filtered by `settings`: causal, or zero-phase
// over each gap-free stretch when settings.zeroPhase. Throws
// std::invalid_argument for settings that cannot filter at this rate.
std::vector<double> filterSeries(const FilterSettings& settings, double sampleRate_hz, std::span<const double> values);

}  // namespace tactiscope::core::dsp
