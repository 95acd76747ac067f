// A capacitive beam's calibration recording (seed 002) turned into the
// calibration's input: the unloaded baseline at the start (C0 and its
// noise, from it alone), the baseline at the end (which measures the drift,
// removed linearly in time before ΔC and the hysteresis are computed), and
// one value per load step — the mean of its settled part — with its
// direction (loading or unloading) from the step before.
//
// Where the load of each sample is known (a load column, as the simulator
// writes the weights it applies, or rows of step means), a step is a run of
// equal load; in a timed recording its settled part starts where the
// wizard's rule (core/calibration/SettledCapture) starts its reading: one
// stable window (capacitiveStabilityDefaults: the soft silicone creeps for
// seconds after a weight is placed), then a fresh window that is stable
// too; a run that never settles so is left out. (From the first stable
// window itself, the settling's tail biased every step toward the load
// before it: 0.16 % of "hysteresis" on a beam with none.) Where only the loads' order is known, the steps are the
// stable plateaus found as the calibration wizard finds them, one per listed load.
#pragma once

#include "core/calibration/CapacitiveCalibration.h"
#include "core/calibration/StabilityMonitor.h"

#include <optional>
#include <vector>

namespace tactiscope::core::calibration {

struct CapacitiveRecording {
    std::vector<double> t_s;  // empty: rows without a time (step means)
    std::vector<double> capacitance_f;
    std::vector<double> load_n;  // per sample; empty when only the order is known
};

struct FoundStep {
    double force_n = 0.0;
    bool loading = true;
    WindowStatistics window;  // its settled part; times are row numbers without a time column
};

struct CapacitiveSteps {
    CapacitiveCalibrationInput input;
    std::vector<FoundStep> steps;        // the loaded ones, as in input.steps
    std::size_t unsettled = 0;           // loaded runs without a stable window, left out
    std::optional<double> finalShift_f;  // the final baseline minus C0
};

// Throws std::invalid_argument for a recording that does not start
// unloaded, whose first baseline never settles, with fewer than two loaded
// steps, or (by order) whose plateaus do not match the loads listed.
// Samples [first, end) of `recording` from where they settle by the
// wizard's rule to `end`, as one window with its mean's standard error;
// without times, all of them. None when they never settle.
std::optional<WindowStatistics> settledWindow(const CapacitiveRecording& recording, std::size_t first, std::size_t end,
                                              const StabilitySettings& stability);

CapacitiveSteps stepsFromLoads(const CapacitiveRecording& recording, const StabilitySettings& stability);
CapacitiveSteps stepsFromPlateaus(const CapacitiveRecording& recording, const std::vector<double>& loads_n,
                                  const StabilitySettings& stability);

}  // namespace tactiscope::core::calibration
