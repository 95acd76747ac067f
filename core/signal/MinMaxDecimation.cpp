// Min/max decimation for plotting (see header).
#include "core/signal/MinMaxDecimation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tactiscope::core::signal {

ColumnExtremes columnExtremes(std::span<const double> y)
{
    // NaN marks "no value" (a gap, a quantity undefined there).
    std::size_t lo = y.size(), hi = y.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (std::isnan(y[i])) continue;
        if (lo == y.size() || y[i] < y[lo]) lo = i;
        if (hi == y.size() || y[i] > y[hi]) hi = i;
    }
    if (lo == y.size()) return {0, 0};
    return {std::min(lo, hi), std::max(lo, hi)};
}

void decimateMinMax(std::span<const double> t, std::span<const double> y, double columnWidth_s,
                    std::vector<double>& tOut, std::vector<double>& yOut)
{
    if (t.size() != y.size()) throw std::invalid_argument("decimateMinMax: t and y differ in length");
    if (!(columnWidth_s > 0.0)) throw std::invalid_argument("decimateMinMax: column width must be positive");
    tOut.clear();
    yOut.clear();
    if (t.empty()) return;

    const double span_s = t.back() - t.front();
    if (static_cast<double>(t.size()) <= 2.0 * (span_s / columnWidth_s + 1.0)) {
        tOut.assign(t.begin(), t.end());
        yOut.assign(y.begin(), y.end());
        return;
    }

    // A sample's column is floor(t / width), evaluated the same way for every
    // sample so that column membership never depends on rounding elsewhere.
    const auto columnOf = [columnWidth_s](double t_s) { return std::floor(t_s / columnWidth_s); };
    std::size_t begin = 0;
    while (begin < t.size()) {
        const double column = columnOf(t[begin]);
        std::size_t end = begin + 1;
        while (end < t.size() && columnOf(t[end]) == column) ++end;
        const auto [first, second] = columnExtremes(y.subspan(begin, end - begin));
        tOut.push_back(t[begin + first]);
        yOut.push_back(y[begin + first]);
        if (second != first) {
            tOut.push_back(t[begin + second]);
            yOut.push_back(y[begin + second]);
        }
        begin = end;
    }
}

std::vector<TimeGap> gapsIn(std::span<const double> t, double maxStep_s)
{
    std::vector<TimeGap> gaps;
    for (std::size_t i = 1; i < t.size(); ++i)
        if (t[i] - t[i - 1] > maxStep_s) gaps.push_back({t[i - 1], t[i]});
    return gaps;
}

void breakAtGaps(std::vector<double>& t, std::vector<double>& y, double maxStep_s)
{
    const auto gaps = gapsIn(t, maxStep_s);
    if (gaps.empty()) return;
    std::vector<double> tBroken, yBroken;
    tBroken.reserve(t.size() + gaps.size());
    yBroken.reserve(t.size() + gaps.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (i > 0 && t[i] - t[i - 1] > maxStep_s) {
            tBroken.push_back(0.5 * (t[i - 1] + t[i]));
            yBroken.push_back(std::numeric_limits<double>::quiet_NaN());
        }
        tBroken.push_back(t[i]);
        yBroken.push_back(y[i]);
    }
    t.swap(tBroken);
    y.swap(yBroken);
}

}  // namespace tactiscope::core::signal
