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
        std::size_t lo = begin;
        std::size_t hi = begin;
        std::size_t end = begin + 1;
        for (; end < t.size() && columnOf(t[end]) == column; ++end) {
            if (y[end] < y[lo]) lo = end;
            if (y[end] > y[hi]) hi = end;
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
