// Calibration of the capacitive beam (seed 002): C0 from a stable unloaded
// baseline, sensitivity from known weights (and/or known tip displacements)
// fitted by least squares, hysteresis between loading and unloading,
// detection limits and the derived relative and pressure sensitivities.
//
// Drift: when a second baseline is taken after the last unload, the
// baseline is taken to drift linearly between the two, and each step's ΔC
// is measured from the baseline interpolated to its time.
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/calibration/CapacitiveSlopeUncertainty.h"
#include "core/calibration/FitCredibility.h"
#include "core/calibration/StabilityMonitor.h"

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::calibration {

struct CapacitiveStep {
    std::optional<double> force_n;         // a known weight's force
    std::optional<double> displacement_m;  // or a known tip displacement
    double capacitance_f = 0.0;            // mean of the step's stable window
    double t_s = 0.0;                      // middle of that window
    bool loading = true;                   // false while weights come off
    double capacitance_u_f = 0.0;          // the mean's standard uncertainty (its own noise); 0: not known
};

struct CapacitiveCalibrationInput {
    WindowStatistics baseline;  // C0 window, values in farads
    std::optional<WindowStatistics> finalBaseline;
    std::vector<CapacitiveStep> steps;
    std::optional<double> contactArea_m2;  // for the pressure sensitivity
    // The beam's stiffness, so force steps alone also give a detection limit
    // in displacement (w = F/k) when no displacement steps were taken.
    std::optional<double> stiffness_n_per_m;
    // The beam's baseline stability, a random walk of σ_w in F/√s (a Type B
    // input: no calibration recording shows it under its noise); its wander
    // about the line between the two baselines then enters the ±.
    std::optional<double> baselineWander_f_per_sqrt_s;
};

struct CapacitiveCalibrationResult {
    double c0_f = 0.0;
    double baselineSigma_f = 0.0;
    double drift_f_per_s = 0.0;
    std::optional<LinearFit> forceFit;  // ΔC [F] against F [N]
    // Its points: the baseline (0, 0) first, then the force steps in order.
    std::vector<double> fitForce_n, fitDelta_f;
    std::optional<LinearFit> displacementFit;  // ΔC [F] against w [m]
    // Largest |ΔC_loading − ΔC_unloading| at the same load, as a fraction of
    // the full-scale ΔC; only when both directions were measured.
    std::optional<double> hysteresis;
    // What the steps' own noise alone could read as hysteresis (twice the
    // largest loading–unloading difference's standard uncertainty, as a
    // fraction of full scale): a hysteresis below it is not the silicone's.
    std::optional<double> hysteresisNoise;
    // How the sensitivity's ± was found: propagated from the steps' noise,
    // the baselines' and the wander (widened when the points scatter beyond
    // them), or, when a step's noise is not known, the points' scatter.
    std::optional<SlopeUncertainty> sensitivityUncertainty;
    std::optional<double> detectionLimit_n;  // 3σ_baseline / sensitivity
    std::optional<double> detectionLimit_m;
    std::optional<double> relativeSensitivity_per_n;   // (ΔC/C0) per newton
    std::optional<double> pressureSensitivity_per_pa;  // (ΔC/C0) per pascal
    // What the numbers above do not say, for people: e.g. loads only ever
    // placed, so the silicone's unfinished creep biases the sensitivity.
    std::vector<std::string> cautions;
    CalibrationRecord record;
};

// Throws std::invalid_argument unless at least two steps have a force, or
// two a displacement.
CapacitiveCalibrationResult calibrateCapacitive(const CapacitiveCalibrationInput& input, const std::string& sensorName,
                                                const std::string& operatorName);

// What "stable" means for the beam's capacitance: over 2 s a drift of at
// most 5 fF/s and a σ of at most 20 fF. The soft silicone creeps for
// seconds after a weight is placed; a shorter or looser window would take
// the step's mean on that creep.
StabilitySettings capacitiveStabilityDefaults();

// A hysteresis of the soft silicone of a few per cent of full scale is the
// sensor's, not a bad point: a point may lie 3 % of the span off the line
// through the others (2 % elsewhere).
CredibilityLimits capacitiveCredibilityLimits();

// 1 mgf, the unit of the paper's weights: 9.80665 µN.
inline constexpr double kMilligramForce_n = 9.80665e-6;

}  // namespace tactiscope::core::calibration
