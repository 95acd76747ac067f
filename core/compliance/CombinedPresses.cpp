// CombinedPresses: inverse-variance weights, the zero part carried linearly.
#include "core/compliance/CombinedPresses.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::compliance {

double CombinedPresses::uncertainty_n_per_m() const
{
    return std::hypot(standardError_n_per_m, zeroUncertainty_n_per_m.value_or(0.0));
}

std::optional<CombinedPresses> combinePresses(std::span<const PressReading> presses)
{
    std::vector<const PressReading*> read;
    for (const auto& p : presses)
        if (p.status == PressStatus::Ok) read.push_back(&p);
    if (read.empty()) return std::nullopt;
    const bool weighted =
        std::ranges::all_of(read, [](const PressReading* p) { return p->standardError_n_per_m > 0.0; });
    const bool zeroKnown =
        std::ranges::all_of(read, [](const PressReading* p) { return p->zeroUncertainty_n_per_m.has_value(); });
    double weights = 0.0, value = 0.0, variance = 0.0, zero = 0.0;
    for (const PressReading* p : read) {
        const double w = weighted ? 1.0 / (p->standardError_n_per_m * p->standardError_n_per_m) : 1.0;
        weights += w;
        value += w * p->stiffness.objectStiffness_n_per_m;
        variance += w * w * p->standardError_n_per_m * p->standardError_n_per_m;
        if (zeroKnown) zero += w * *p->zeroUncertainty_n_per_m;
    }
    CombinedPresses combined;
    combined.presses = read.size();
    combined.stiffness_n_per_m = value / weights;
    combined.standardError_n_per_m = std::sqrt(variance) / weights;
    if (zeroKnown) combined.zeroUncertainty_n_per_m = zero / weights;
    const bool uncertain =
        std::ranges::all_of(read, [](const PressReading* p) { return p->uncertainty_n_per_m() > 0.0; });
    if (read.size() >= 2 && uncertain) {
        double chi2 = 0.0;
        for (const PressReading* p : read) {
            const double deviation = (p->stiffness.objectStiffness_n_per_m - combined.stiffness_n_per_m);
            chi2 += deviation * deviation / (p->uncertainty_n_per_m() * p->uncertainty_n_per_m());
        }
        const double dof = static_cast<double>(read.size() - 1);
        combined.birgeRatio = std::sqrt(chi2 / dof);
        combined.consistent = *combined.birgeRatio <= 1.0 + 3.0 / std::sqrt(2.0 * dof);
        if (!combined.consistent) combined.standardError_n_per_m *= *combined.birgeRatio;
    }
    return combined;
}

}  // namespace tactiscope::core::compliance
