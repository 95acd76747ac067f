// Checks that sample times are strictly increasing and evenly spaced, as the
// detector's lags (whole samples) require, and returns the interval.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>

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
    explicit UniformTimeBaseCheck(double tolerance = 0.01)
        : m_tolerance(tolerance)
    {
    }
    // The next times; a TimeBaseError's row is the index in `t`.
    void add(std::span<const double> t);
    // The mean interval of every sample so far, the most precise there is.
    double interval_s() const;

private:
    double m_tolerance;
    double m_typical = 0.0;
    double m_first = 0.0;
    double m_last = 0.0;
    std::size_t m_count = 0;
};

}  // namespace tactiscope::core::io
