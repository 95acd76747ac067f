// Min/max decimation of a scrolling window, kept up to date sample by
// sample: the live plot's per-frame cost then follows the samples that
// arrived, not the window's length. Same columns and the same rules as
// decimateMinMax (columns at absolute multiples of the width; each column's
// minimum and maximum in time order; NaN is no value, a column of nothing
// but NaN keeps one NaN to break the line), except that it never passes
// sparse data through unchanged.
#pragma once

#include <cstddef>
#include <deque>
#include <span>
#include <vector>

namespace tactiscope::core::signal {

class ScrollingMinMax {
public:
    // Throws std::invalid_argument unless columnWidth_s > 0.
    explicit ScrollingMinMax(double columnWidth_s);

    double columnWidth_s() const { return m_width_s; }
    // Samples continuing the previous ones (t non-decreasing, equal lengths).
    void append(std::span<const double> t, std::span<const double> y);
    // Forgets the closed columns before the one holding t_s.
    void dropBefore(double t_s);
    // The points of the closed columns and of the column still filling, in
    // time order; tOut and yOut are replaced.
    void points(std::vector<double>& tOut, std::vector<double>& yOut) const;

private:
    double columnOf(double t_s) const;
    void closeColumn();

    double m_width_s;
    std::deque<double> m_t, m_y;           // points of closed columns
    std::vector<double> m_openT, m_openY;  // samples of the column still filling
};

}  // namespace tactiscope::core::signal
