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

}  // namespace tactiscope::core::io
