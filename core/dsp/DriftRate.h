// A channel's drift: the slope of a straight line through the means of
// ~100 equal intervals of the recording (the "per-interval statistics" of
// long runs), with its standard uncertainty (k = 1) from the scatter of
// those means about the line. Interval means, not every sample, so noise
// that is not white (hum, a hand's tremor, 1/f) is averaged where it
// lives and what is left shows in the ±, rather than a ± that only white
// noise would earn.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace tactiscope::core::dsp {

// A drift read over less than this is the noise's, its ± alone wider than
// any drift worth knowing: none is given (live, in reports, by `health`).
inline constexpr double kShortestDrift_s = 30.0;

struct Drift {
    double rate_per_s = 0.0;
    double standardUncertainty_per_s = 0.0;  // k = 1
    std::size_t intervals = 0;
};

class DriftAccumulator {
public:
    // `intervalSamples` per interval (expected samples / 100, say).
    explicit DriftAccumulator(double sampleRate_hz, std::uint64_t intervalSamples);

    // The next sample; NaN where missing (it is still counted for time).
    void push(double value);
    // None with fewer than 3 intervals holding half their samples or more.
    std::optional<Drift> result() const;
    // The time the samples pushed span, missing ones included.
    double span_s() const { return static_cast<double>(m_index) / m_rate_hz; }

private:
    void closeInterval();

    double m_rate_hz;
    std::uint64_t m_intervalSamples;
    std::uint64_t m_index = 0;
    std::uint64_t m_inInterval = 0;
    double m_sum = 0.0;
    double m_indexSum = 0.0;
    std::uint64_t m_count = 0;
    std::vector<double> m_t;     // each kept interval's mean time, s
    std::vector<double> m_mean;  // and its mean value
};

// Intervals of a recording of `samples` for ~100 of them (one sample at least each).
std::uint64_t driftIntervalSamples(std::uint64_t samples);

}  // namespace tactiscope::core::dsp
