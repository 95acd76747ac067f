// A moving average of the last N samples, for a live view (causal). Its
// running sum is recomputed from the window once per N samples, so an
// hour's stream carries no creeping rounding error, and the same samples
// always give the same outputs bit for bit (live and re-analysis agree).
#pragma once

#include <cstddef>
#include <vector>

namespace tactiscope::core::dsp {

class MovingAverage {
public:
    explicit MovingAverage(std::size_t length = 1);

    std::size_t length() const { return m_window.size(); }
    // The first input after construction or reset() fills the window with itself.
    double process(double x);
    void reset() { m_started = false; }

private:
    std::vector<double> m_window;
    std::size_t m_next = 0;
    double m_sum = 0.0;
    bool m_started = false;
};

}  // namespace tactiscope::core::dsp
