// Min/max decimation for drawing: reduces a time series to at most two points
// per screen column (the column's minimum and maximum, in time order), so a
// plot shows every peak of a long trace at a cost set by the screen width,
// not by the number of samples.
//
// Columns are aligned to absolute multiples of the column width in time, not
// to the first sample, so a scrolling trace does not shimmer as its window
// slides.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core::signal {

// The samples that stand for one column: the indices of its minimum and
// maximum in time order (equal when one sample is both). NaN takes no part;
// a column of nothing but NaN is its first sample, so the line breaks there.
struct ColumnExtremes {
    std::size_t first = 0;
    std::size_t second = 0;
};
ColumnExtremes columnExtremes(std::span<const double> y);

// t must be non-decreasing and the same length as y; columnWidth_s > 0.
// When there are no more than two samples per column on average, the samples
// are returned unchanged. NaN samples are "no value": a column's extremes
// ignore them, and a column with nothing else yields one NaN point (a break
// in the drawn line). tOut and yOut are replaced.
void decimateMinMax(std::span<const double> t, std::span<const double> y, double columnWidth_s,
                    std::vector<double>& tOut, std::vector<double>& yOut);

// Where a trace has no samples: every step of more than maxStep_s between
// consecutive points of t (non-decreasing) is a gap, from the point before
// it to the point after it. A display draws these as gaps, never joined.
struct TimeGap {
    double from_s = 0.0;
    double to_s = 0.0;
};
std::vector<TimeGap> gapsIn(std::span<const double> t, double maxStep_s);

// Puts a NaN point (a break in the drawn line) in the middle of each gap of
// more than maxStep_s in the points (t, y).
void breakAtGaps(std::vector<double>& t, std::vector<double>& y, double maxStep_s);

}  // namespace tactiscope::core::signal
