// ExactOverview: equal stretches, each its NaN-free min and max.
#include "core/derived/ExactOverview.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::core::derived {

void appendExactOverview(std::span<const double> values, std::uint64_t first, std::size_t stretches,
                         std::vector<storage::OverviewPoint>& into)
{
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    const std::uint64_t size =
        std::max<std::uint64_t>(1, (values.size() + stretches - 1) / std::max<std::size_t>(1, stretches));
    for (std::uint64_t at = 0; at < values.size(); at += size) {
        storage::OverviewPoint point{first + at, std::min<std::uint64_t>(size, values.size() - at), kNaN, kNaN};
        for (std::uint64_t s = at; s < at + point.count; ++s) {
            if (std::isnan(values[s])) continue;
            point.min = std::isnan(point.min) ? values[s] : std::min(point.min, values[s]);
            point.max = std::isnan(point.max) ? values[s] : std::max(point.max, values[s]);
        }
        into.push_back(point);
    }
}

}  // namespace tactiscope::core::derived
