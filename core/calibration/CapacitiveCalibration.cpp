// C0, sensitivity, hysteresis and detection limits of the capacitive beam.
#include "core/calibration/CapacitiveCalibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace tactiscope::core::calibration {
namespace {

struct Hysteresis {
    double fraction = 0.0;  // the largest loading/unloading difference at equal load, of full scale
    double noise = 0.0;     // twice the largest such difference's standard uncertainty, of full scale
};

// Over the loads measured both ways; none without such a load.
std::optional<Hysteresis> hysteresisOf(const std::vector<std::pair<double, bool>>& loadAndDirection,
                                       const std::vector<double>& deltaC, const std::vector<double>& u)
{
    struct Side {
        double sum = 0.0, variance = 0.0;
        std::size_t count = 0;
        double mean() const { return sum / static_cast<double>(count); }
        // The variance of the mean of its steps.
        double meanVariance() const { return variance / static_cast<double>(count * count); }
    };
    std::map<double, std::pair<Side, Side>> byLoad;
    for (std::size_t i = 0; i < deltaC.size(); ++i) {
        auto& entry = byLoad[loadAndDirection[i].first];
        Side& side = loadAndDirection[i].second ? entry.first : entry.second;
        side.sum += deltaC[i];
        side.variance += u[i] * u[i];
        ++side.count;
    }
    // Full scale: the largest change from the unloaded baseline.
    double fullScale = 0.0;
    for (double d : deltaC) fullScale = std::max(fullScale, std::abs(d));
    std::optional<Hysteresis> worst;
    for (const auto& [load, sides] : byLoad) {
        if (sides.first.count == 0 || sides.second.count == 0 || !(fullScale > 0.0)) continue;
        if (!worst) worst.emplace();
        worst->fraction = std::max(worst->fraction, std::abs(sides.first.mean() - sides.second.mean()) / fullScale);
        worst->noise = std::max(worst->noise,
                                2.0 * std::sqrt(sides.first.meanVariance() + sides.second.meanVariance()) / fullScale);
    }
    return worst;
}

}  // namespace

CapacitiveCalibrationResult calibrateCapacitive(const CapacitiveCalibrationInput& in, const std::string& sensorName,
                                                const std::string& operatorName)
{
    CapacitiveCalibrationResult r;
    r.c0_f = in.baseline.mean;
    r.baselineSigma_f = in.baseline.sigma;
    if (in.finalBaseline && in.finalBaseline->middle_s() > in.baseline.middle_s())
        r.drift_f_per_s =
            (in.finalBaseline->mean - in.baseline.mean) / (in.finalBaseline->middle_s() - in.baseline.middle_s());

    std::vector<double> force, forceDelta, forceU, forceT, displacement, displacementDelta;
    std::vector<std::pair<double, bool>> forceDirection, displacementDirection;
    for (const CapacitiveStep& step : in.steps) {
        const double delta = step.capacitance_f - (r.c0_f + r.drift_f_per_s * (step.t_s - in.baseline.middle_s()));
        if (step.force_n) {
            force.push_back(*step.force_n);
            forceDelta.push_back(delta);
            forceDirection.emplace_back(*step.force_n, step.loading);
            forceU.push_back(step.capacitance_u_f);
            forceT.push_back(step.t_s);
        }
        if (step.displacement_m) {
            displacement.push_back(*step.displacement_m);
            displacementDelta.push_back(delta);
            displacementDirection.emplace_back(*step.displacement_m, step.loading);
        }
    }
    if (force.size() < 2 && displacement.size() < 2)
        throw std::invalid_argument("capacitive calibration needs at least two loads or two displacements");
    // The baseline itself is the zero-load point of each fit.
    const auto withZero = [](const std::vector<double>& v) {
        std::vector<double> out{0.0};
        out.insert(out.end(), v.begin(), v.end());
        return out;
    };

    CalibrationRecord& record = r.record;
    record.kind = kCapacitiveKind;
    record.sensorName = sensorName;
    record.operatorName = operatorName;
    record.timestampUtc = utcTimestampNow();
    record.values = {{"c0_pf", r.c0_f * 1e12},
                     {"baseline_sigma_pf", r.baselineSigma_f * 1e12},
                     {"drift_pf_per_s", r.drift_f_per_s * 1e12}};

    if (force.size() >= 2) {
        r.fitForce_n = withZero(force);
        r.fitDelta_f = withZero(forceDelta);
        r.forceFit = fitLine(r.fitForce_n, r.fitDelta_f);
        SlopeUncertaintyInput propagation{
            {}, {in.baseline.middle_s(), in.baseline.meanStandardError}, std::nullopt, in.baselineWander_f_per_sqrt_s};
        if (in.finalBaseline && in.finalBaseline->middle_s() > in.baseline.middle_s())
            propagation.final = BaselineReading{in.finalBaseline->middle_s(), in.finalBaseline->meanStandardError};
        for (std::size_t i = 0; i < force.size(); ++i)
            propagation.steps.push_back({force[i], r.forceFit->residuals[i + 1], forceU[i], forceT[i]});
        r.sensitivityUncertainty = propagatedSlopeUncertainty(propagation);
        if (r.sensitivityUncertainty) {
            r.forceFit->slopeStandardError = r.sensitivityUncertainty->u_f_per_n;
            if (r.sensitivityUncertainty->widened) {
                char text[320];
                std::snprintf(text, sizeof text,
                              "the points scatter beyond their steps' noise%s (χ²/ν = %.1f): the sensitivity's ± is "
                              "widened by √(χ²/ν); %s",
                              in.baselineWander_f_per_sqrt_s ? " and the baseline's wander" : "",
                              r.sensitivityUncertainty->chiSquarePerDegree,
                              in.baselineWander_f_per_sqrt_s
                                  ? "a creep, a hysteresis or a step read before it settled"
                                  : "a baseline that wanders between its zeros (state the beam's baseline stability), "
                                    "a creep, a hysteresis or a step read before it settled");
                r.cautions.emplace_back(text);
            }
        }
        // A stated stability far beyond what the two zeros show is a slip
        // of its value or unit (a random walk moves 30× less than its σ√T
        // about 2 % of the time).
        if (in.baselineWander_f_per_sqrt_s && propagation.final) {
            const double implied =
                *in.baselineWander_f_per_sqrt_s * std::sqrt(propagation.final->t_s - propagation.first.t_s);
            const double seen = std::max(std::abs(in.finalBaseline->mean - in.baseline.mean),
                                         3.0 * std::hypot(propagation.first.u_f, propagation.final->u_f));
            if (implied > 30.0 * seen) {
                char text[320];
                std::snprintf(text, sizeof text,
                              "the baseline stability given (%.3g pF/√s) would move the baseline about %.3g pF "
                              "between the two zeros, %.0f× what they show (%.3g pF): check its value and unit",
                              *in.baselineWander_f_per_sqrt_s * 1e12, implied * 1e12, implied / seen, seen * 1e12);
                r.cautions.emplace_back(text);
            }
        }
        const double slope = r.forceFit->slope;  // F per N
        if (const auto h = hysteresisOf(forceDirection, forceDelta, forceU)) {
            r.hysteresis = h->fraction;
            if (h->noise > 0.0) r.hysteresisNoise = h->noise;
        }
        r.detectionLimit_n = 3.0 * r.baselineSigma_f / slope;
        r.relativeSensitivity_per_n = slope / r.c0_f;
        if (in.contactArea_m2) r.pressureSensitivity_per_pa = *r.relativeSensitivity_per_n * *in.contactArea_m2;
        record.values.insert(record.values.end(),
                             {{"sensitivity_pf_per_mn", slope * 1e9},
                              {"intercept_pf", r.forceFit->intercept * 1e12},
                              {"r_squared", r.forceFit->rSquared},
                              {"detection_limit_mn", *r.detectionLimit_n * 1e3},
                              {"relative_sensitivity_per_mn", *r.relativeSensitivity_per_n * 1e-3}});
        if (r.hysteresis) record.values.emplace_back("hysteresis_fraction", *r.hysteresis);
        if (r.pressureSensitivity_per_pa)
            record.values.emplace_back("pressure_sensitivity_per_kpa", *r.pressureSensitivity_per_pa * 1e3);
        record.fit = *r.forceFit;
        // The silicone still creeps when a step's window is taken: under a
        // load placed it has not yet bent as far as it will, and after one
        // removed not yet come back, so loading reads the slope low and
        // unloading high. Only with both do they cancel.
        if (std::ranges::none_of(forceDirection, [](const auto& step) { return !step.second; }))
            r.cautions.push_back(
                "loads only placed, never removed: the silicone's creep, unfinished at each step, reads the "
                "sensitivity low by the part of the creep still to come (a bias the ±, the points' scatter, "
                "does not include); take the weights off again one at a time for a creep-balanced slope and "
                "the hysteresis");
    }
    if (displacement.size() >= 2) {
        r.displacementFit = fitLine(withZero(displacement), withZero(displacementDelta));
        r.detectionLimit_m = 3.0 * r.baselineSigma_f / r.displacementFit->slope;
        record.values.insert(record.values.end(),
                             {{"displacement_sensitivity_pf_per_mm", r.displacementFit->slope * 1e9},
                              {"detection_limit_mm", *r.detectionLimit_m * 1e3}});
        if (!r.forceFit) record.fit = *r.displacementFit;
    } else if (r.detectionLimit_n && in.stiffness_n_per_m && *in.stiffness_n_per_m > 0.0) {
        r.detectionLimit_m = *r.detectionLimit_n / *in.stiffness_n_per_m;
        record.values.emplace_back("detection_limit_mm", *r.detectionLimit_m * 1e3);
    }
    return r;
}

StabilitySettings capacitiveStabilityDefaults()
{
    return {2.0, 5e-15, 20e-15};
}

CredibilityLimits capacitiveCredibilityLimits()
{
    CredibilityLimits limits;
    limits.maximumOffLine = 0.03;
    return limits;
}

}  // namespace tactiscope::core::calibration
