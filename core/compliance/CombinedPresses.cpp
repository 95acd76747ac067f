// CombinedPresses: inverse-variance weights, the zero part carried linearly.
#include "core/compliance/CombinedPresses.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tactiscope::core::compliance {

double CombinedPresses::uncertainty_n_per_m() const
{
    return std::hypot(standardError_n_per_m, zeroUncertainty_n_per_m.value_or(0.0));
}

namespace {

struct Value {
    double value = 0.0;
    double noise = 0.0;          // its standard error
    std::optional<double> zero;  // the zero's part, when known
};

// Inverse-variance weights of the noise (equal when one has none), the
// zero's part carried linearly, and the Birge ratio over the whole u's.
CombinedPresses combineValues(const std::vector<Value>& values)
{
    const bool weighted = std::ranges::all_of(values, [](const Value& v) { return v.noise > 0.0; });
    const bool zeroKnown = std::ranges::all_of(values, [](const Value& v) { return v.zero.has_value(); });
    double weights = 0.0, sum = 0.0, variance = 0.0, zero = 0.0;
    for (const Value& v : values) {
        const double w = weighted ? 1.0 / (v.noise * v.noise) : 1.0;
        weights += w;
        sum += w * v.value;
        variance += w * w * v.noise * v.noise;
        if (zeroKnown) zero += w * *v.zero;
    }
    CombinedPresses combined;
    combined.presses = values.size();
    combined.stiffness_n_per_m = sum / weights;
    combined.standardError_n_per_m = std::sqrt(variance) / weights;
    if (zeroKnown) combined.zeroUncertainty_n_per_m = zero / weights;
    const auto whole = [](const Value& v) { return std::hypot(v.noise, v.zero.value_or(0.0)); };
    if (values.size() >= 2 && std::ranges::all_of(values, [&](const Value& v) { return whole(v) > 0.0; })) {
        double chi2 = 0.0;
        for (const Value& v : values) {
            const double deviation = v.value - combined.stiffness_n_per_m;
            chi2 += deviation * deviation / (whole(v) * whole(v));
        }
        const double dof = static_cast<double>(values.size() - 1);
        combined.birgeRatio = std::sqrt(chi2 / dof);
        combined.consistent = *combined.birgeRatio <= 1.0 + 3.0 / std::sqrt(2.0 * dof);
        if (!combined.consistent) combined.standardError_n_per_m *= *combined.birgeRatio;
    }
    return combined;
}

bool isBound(const PressReading& p)
{
    return p.status == PressStatus::BelowRange || p.status == PressStatus::AboveRange;
}

// Presses at the probe's edge taken together: the bound at 2u from their
// mean ratio towards the inside, the way most of their bounds point (none
// when that is the limit itself).
CombinedPresses boundOfRatios(const sensors::CompliancePair& pair, const CombinedPresses& ratio, PressStatus way)
{
    const double q = ratio.stiffness_n_per_m, u = ratio.uncertainty_n_per_m();
    CombinedPresses r;
    r.status = way;
    r.presses = ratio.presses;
    r.birgeRatio = ratio.birgeRatio;
    r.consistent = ratio.consistent;
    const auto k = pair.objectStiffness(way == PressStatus::BelowRange ? q + 2.0 * u : q - 2.0 * u);
    if (k.range == sensors::ComplianceRange::InRange) r.bound_n_per_m = k.objectStiffness_n_per_m;
    return r;
}

}  // namespace

std::optional<CombinedPresses> combinePresses(const sensors::CompliancePair& pair,
                                              std::span<const PressReading> presses)
{
    std::vector<Value> values;
    if (std::ranges::any_of(presses, isBound)) {
        // At the probe's edge: every press not clipped, as a ratio.
        const auto below =
            std::ranges::count_if(presses, [](const auto& p) { return p.status == PressStatus::BelowRange; });
        const auto above =
            std::ranges::count_if(presses, [](const auto& p) { return p.status == PressStatus::AboveRange; });
        for (const auto& p : presses) {
            if (p.status == PressStatus::Clipped) continue;
            std::optional<double> zero;
            if (p.ratioUncertainty > p.ratioStandardError || p.zeroUncertainty_n_per_m)
                zero = std::sqrt(std::max(0.0, p.ratioUncertainty * p.ratioUncertainty -
                                                   p.ratioStandardError * p.ratioStandardError));
            values.push_back({p.q, p.ratioStandardError, zero});
        }
        return boundOfRatios(pair, combineValues(values),
                             below >= above ? PressStatus::BelowRange : PressStatus::AboveRange);
    }
    for (const auto& p : presses)
        if (p.status == PressStatus::Ok)
            values.push_back({p.stiffness.objectStiffness_n_per_m, p.standardError_n_per_m, p.zeroUncertainty_n_per_m});
    if (values.empty()) return std::nullopt;
    CombinedPresses combined = combineValues(values);
    // Its limits through the exact map, from the ratio's u.
    const double dQdk = pair.sensitivity_m_per_n(combined.stiffness_n_per_m);
    const double q = pair.forceRatio(combined.stiffness_n_per_m), u = combined.uncertainty_n_per_m() * dQdk;
    // (Presses that disagree may widen it past a limit: 0 or ∞ there.)
    combined.lowerLimit_n_per_m = q - 2.0 * u > 1.0 ? pair.objectStiffness(q - 2.0 * u).objectStiffness_n_per_m : 0.0;
    combined.upperLimit_n_per_m = q + 2.0 * u < pair.qMax() ? pair.objectStiffness(q + 2.0 * u).objectStiffness_n_per_m
                                                            : std::numeric_limits<double>::infinity();
    return combined;
}

}  // namespace tactiscope::core::compliance
