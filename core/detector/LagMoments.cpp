// LagMoments set-up.
#include "core/detector/LagMoments.h"

#include <algorithm>

namespace tactiscope::core::detector {

void LagMoments::assign(const std::vector<std::uint32_t>& lags, const std::vector<double>& forgettingFactors)
{
    lagCount = lags.size();
    paddedCount = (lagCount + kLaneWidth - 1) / kLaneWidth * kLaneWidth;
    lag.resize(paddedCount);
    weight.assign(paddedCount, 0.0);
    // Padding lanes: r = ½ keeps their (ignored) covariance bounded.
    forgetting.assign(paddedCount, 0.5);
    for (std::size_t i = 0; i < paddedCount; ++i) {
        lag[i] = i < lagCount ? lags[i] : lags.back() + static_cast<std::uint32_t>(i - lagCount + 1);
    }
    for (std::size_t i = 0; i < lagCount; ++i) {
        if (forgettingFactors.empty()) {
            weight[i] = 1.0;
        } else {
            forgetting[i] = forgettingFactors[i];
            weight[i] = 1.0 - forgettingFactors[i];
        }
    }
    contiguous = true;
    for (std::size_t i = 0; i < paddedCount; ++i) contiguous = contiguous && lag[i] == lag[0] + i;
    for (auto& m : mean) m.assign(paddedCount, 0.0);
    for (auto& s : moment) s.assign(paddedCount, 0.0);
}

void LagMoments::zero()
{
    for (auto& m : mean) std::fill(m.begin(), m.end(), 0.0);
    for (auto& s : moment) std::fill(s.begin(), s.end(), 0.0);
}

}  // namespace tactiscope::core::detector
