// The last stretch of a signal, kept to judge whether a zero may be taken
// from it: its mean, its spread, and how far its second half moved from its
// first half measured against its own noise. A processor's tare rule reads
// these (LivePalpation, LiveCapacitive): the zero is the mean of a stretch
// already seen and judged steady, never of samples still to come.
#pragma once

#include <cstddef>
#include <deque>

namespace tactiscope::core::signal {

class SteadyWindow {
public:
    explicit SteadyWindow(std::size_t length);  // samples; at least 4

    void push(double value);
    void clear() { m_values.clear(); }
    bool full() const { return m_values.size() == m_length; }
    std::size_t length() const { return m_length; }

    double mean() const;
    double spread() const;  // max − min
    // σ/√n of the values (n − 1): the uncertainty of mean() for white noise.
    double standardErrorOfMean() const;
    // The second half's mean minus the first half's.
    double halfShift() const;
    // |halfShift()| over its standard error from the scatter within the
    // halves: about 1 for a steady noisy signal, large for a step or a ramp.
    // Infinite for a noiseless signal that moved, 0 for one that did not.
    double halfShiftScore() const;
    // The same for every split of the window in two, at its
    // largest: a step anywhere in the window, which the halves miss when
    // it falls within one of them in a short window (five samples at
    // 10 Hz). Infinite for a noiseless signal that moved.
    double stepScore() const;

private:
    std::size_t m_length;
    std::deque<double> m_values;
};

}  // namespace tactiscope::core::signal
