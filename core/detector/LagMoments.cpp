// LagMoments set-up.
#include "core/detector/LagMoments.h"

#include <algorithm>

namespace tactiscope::core::detector {

void LagMoments::assign(const std::vector<std::uint32_t>& lags, const std::vector<double>& weights)
{
    lagCount = lags.size();
    paddedCount = (lagCount + kLaneWidth - 1) / kLaneWidth * kLaneWidth;
    lag.assign(paddedCount, 0);
    weight.assign(paddedCount, 0.0);
    std::copy(lags.begin(), lags.end(), lag.begin());
    std::copy(weights.begin(), weights.end(), weight.begin());
    for (auto& m : mean) m.assign(paddedCount, 0.0);
    for (auto& s : moment) s.assign(paddedCount, 0.0);
}

void LagMoments::zero()
{
    for (auto& m : mean) std::fill(m.begin(), m.end(), 0.0);
    for (auto& s : moment) std::fill(s.begin(), s.end(), 0.0);
}

}  // namespace tactiscope::core::detector
