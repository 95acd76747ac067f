// Min/max decimation for plotting (see header).
#include "core/signal/MinMaxDecimation.h"

#include <algorithm>
#include <cmath>
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

}  // namespace tactiscope::core::signal
