// CalibrationDrift: spread, first-to-last change and trend of a value.
#include "core/calibration/CalibrationDrift.h"

#include "core/calibration/LinearFit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace tactiscope::core::calibration {

DriftSummary summarizeDrift(std::span<const double> t_s, std::span<const double> values)
{
    if (values.empty() || t_s.size() != values.size())
        throw std::invalid_argument("calibration drift needs values, one time each");
    DriftSummary d;
    d.count = values.size();
    const auto n = static_cast<double>(values.size());
    d.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
    if (values.size() > 1) {
        double squares = 0.0;
        for (double v : values) squares += (v - d.mean) * (v - d.mean);
        d.standardDeviation = std::sqrt(squares / (n - 1.0));
    }
    const auto [oldest, newest] = std::minmax_element(t_s.begin(), t_s.end());
    const double first = values[static_cast<std::size_t>(oldest - t_s.begin())];
    const double last = values[static_cast<std::size_t>(newest - t_s.begin())];
    d.firstToLast = first != 0.0 ? (last - first) / first : 0.0;
    d.span_s = *newest - *oldest;
    if (d.count >= kTrendRecords && d.span_s >= kTrendSpan_s) {
        constexpr double kYear_s = 365.25 * 86400.0;
        const auto fit = fitLine(t_s, values);
        const double dof = n - 2.0;  // ≥ 8: kTrendRecords
        d.trend = DriftTrend{fit.slope * kYear_s, fit.slopeStandardError * std::sqrt(dof / (dof - 2.0)) * kYear_s};
    }
    return d;
}

}  // namespace tactiscope::core::calibration
