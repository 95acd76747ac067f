// Checks that sample times are strictly increasing and evenly spaced, as the
// detector's lags (whole samples) require, and returns the interval. Where
// asked, a step of a whole number of intervals is a gap (samples lost on
// the way, rows an export leaves out), not an irregular time base.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace tactiscope::core::io {

// Thrown for times that are not a uniform time base; `row` is the index of
// the first offending sample.
class TimeBaseError : public std::runtime_error {
public:
    TimeBaseError(const std::string& message, std::size_t row)
        : std::runtime_error(message),
          m_row(row)
    {
    }
    std::size_t row() const { return m_row; }

private:
    std::size_t m_row;
};

// The mean interval of t (at least two samples). Every step must be positive
// and within `tolerance` (relative) of the median step.
double uniformSampleInterval(std::span<const double> t, double tolerance = 0.01);

// The same check over times read a block at a time: the first block (two
// samples at least) sets the typical step, its median; every later step,
// across blocks too, must be within `tolerance` of it.
class UniformTimeBaseCheck {
public:
    enum class Gaps { Refused, Allowed };
    explicit UniformTimeBaseCheck(double tolerance = 0.01, Gaps gaps = Gaps::Refused)
        : m_tolerance(tolerance),
          m_gapsAllowed(gaps == Gaps::Allowed)
    {
    }
    // The next times; a TimeBaseError's row is the index in `t`.
    void add(std::span<const double> t);
    // The mean interval of every sample so far, gaps left out, the most
    // precise there is.
    double interval_s() const;
    // With gaps allowed: the index (from the first time added) of each
    // sample that follows a gap, and how many samples the gaps miss.
    const std::vector<std::uint64_t>& samplesAfterGaps() const { return m_afterGaps; }
    std::uint64_t samplesMissing() const { return m_missing; }

private:
    double m_tolerance;
    bool m_gapsAllowed;
    double m_typical = 0.0;
    double m_first = 0.0;
    double m_last = 0.0;
    double m_gapSpan_s = 0.0;  // the steps that were gaps, summed
    std::size_t m_count = 0;
    std::vector<std::uint64_t> m_afterGaps;
    std::uint64_t m_missing = 0;
};

}  // namespace tactiscope::core::io
