// Min/max decimation for plotting (see header).
#include "core/signal/MinMaxDecimation.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::signal {

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
        // NaN marks "no value" (a gap, a quantity undefined there): it takes
        // no part in the extremes, and a column of nothing but NaN keeps one
        // NaN so the drawn line breaks there.
        std::size_t lo = end;
        std::size_t hi = end;
        for (std::size_t i = begin; i < end; ++i) {
            if (std::isnan(y[i])) continue;
            if (lo == end || y[i] < y[lo]) lo = i;
            if (hi == end || y[i] > y[hi]) hi = i;
        }
        if (lo == end) {
            tOut.push_back(t[begin]);
            yOut.push_back(y[begin]);
            begin = end;
            continue;
        }
        const std::size_t first = lo < hi ? lo : hi;
        const std::size_t second = lo < hi ? hi : lo;
        tOut.push_back(t[first]);
        yOut.push_back(y[first]);
        if (second != first) {
            tOut.push_back(t[second]);
            yOut.push_back(y[second]);
        }
        begin = end;
    }
}

}  // namespace tactiscope::core::signal
