// ClockAlignment: the fastest pair per bin, their lower hull, the hull's
// edge over their mean.
#include "core/timing/ClockAlignment.h"

#include <cmath>
#include <vector>

namespace tactiscope::core::timing {

void ClockAlignment::add(double device_s, double arrival_s)
{
    if (!std::isfinite(device_s) || !std::isfinite(arrival_s)) return;
    const auto bin = static_cast<long long>(std::floor(device_s / kClockBin_s));
    if (m_lastBin && bin < *m_lastBin) return;  // a stamp gone back: not this clock
    ++m_pairs;
    const Point point{device_s, arrival_s - device_s};
    if (m_lastBin && bin == *m_lastBin) {
        if (point.lag_s < m_points.back().lag_s) m_points.back() = point;
    } else {
        m_points.push_back(point);
        m_lastBin = bin;
    }
    while (m_points.size() > 2 && device_s - m_points.front().device_s > kClockWindow_s) m_points.pop_front();
}

std::optional<ClockMapping> ClockAlignment::mapping() const
{
    if (m_points.size() < 2) return std::nullopt;
    // Lag against device time, relative to the first point (the lag is the
    // offset plus drift times device time: a line, however long the session).
    const double x0 = m_points.front().device_s;
    const double y0 = m_points.front().lag_s;
    std::vector<std::size_t> hull;
    const auto x = [&](std::size_t i) { return m_points[i].device_s - x0; };
    const auto y = [&](std::size_t i) { return m_points[i].lag_s - y0; };
    double meanX = 0.0;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        meanX += x(i);
        // Andrew's monotone chain, lower half: pop while the last two and
        // this one do not turn left (the middle one is not below the chord).
        while (hull.size() >= 2) {
            const std::size_t a = hull[hull.size() - 2], b = hull.back();
            if ((x(b) - x(a)) * (y(i) - y(a)) - (y(b) - y(a)) * (x(i) - x(a)) > 0.0) break;
            hull.pop_back();
        }
        hull.push_back(i);
    }
    meanX /= static_cast<double>(m_points.size());
    // The edge over the mean: of all lines under every point, the one whose
    // sum of distances to them is least.
    std::size_t edge = 0;
    while (edge + 2 < hull.size() && x(hull[edge + 1]) < meanX) ++edge;
    const std::size_t a = hull[edge], b = hull[edge + 1];
    const double slope = (y(b) - y(a)) / (x(b) - x(a));
    ClockMapping mapping;
    mapping.reference_s = x0 + meanX;
    mapping.offset_s = y0 + y(a) + slope * (meanX - x(a));
    mapping.drift = slope;
    mapping.span_s = x(m_points.size() - 1);
    mapping.pairs = m_pairs;
    return mapping;
}

}  // namespace tactiscope::core::timing
