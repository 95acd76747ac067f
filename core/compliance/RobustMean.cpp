// One k·σ rejection, then the statistics of the kept values.
#include "core/compliance/RobustMean.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::compliance {

RobustMean robustMean(std::span<const double> values, double k, std::vector<bool>* keptOut)
{
    if (values.empty()) throw std::invalid_argument("robust mean of no values");
    if (!(k > 0.0)) throw std::invalid_argument("rejection limit must be positive");
    std::vector<bool> kept(values.size(), true);
    RobustMean result;
    for (int round = 0; round < 2; ++round) {  // statistics, cut; statistics of the kept
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (kept[i]) {
                sum += values[i];
                ++n;
            }
        }
        const double mean = sum / static_cast<double>(n);
        double squares = 0.0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (kept[i]) squares += (values[i] - mean) * (values[i] - mean);
        }
        const double sigma = n > 1 ? std::sqrt(squares / static_cast<double>(n - 1)) : 0.0;
        result = {mean, sigma, sigma / std::sqrt(static_cast<double>(n)), n, values.size() - n};
        if (round == 1) break;
        for (std::size_t i = 0; i < values.size() && sigma > 0.0; ++i) {
            if (std::abs(values[i] - mean) > k * sigma) kept[i] = false;
        }
    }
    if (keptOut) *keptOut = kept;
    return result;
}

}  // namespace tactiscope::core::compliance
