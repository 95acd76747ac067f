// The paper's reading procedure (seed 001, section 3) over a recording: the
// probe is held at displacements 1 mm apart, 1000 readings of both forces
// are taken at each, each force's readings beyond 3σ are rejected once, and
// the step's Q and k_o come from the two means (StepReader). The overall
// k_o is the mean of the steps' with its standard error from their scatter.
//
// A recording's samples are assigned to the step nearest their displacement
// (in contact only: both forces above the contact threshold; the first step
// is one step into the object, as the paper's first is 1 mm); a step takes
// its first N samples in time order. A step with fewer is listed as short
// and left out, rather than read on fewer readings than the procedure says.
#pragma once

#include "core/compliance/StiffnessReadings.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::core::compliance {

struct StepSettings {
    double step_m = 1e-3;
    std::size_t readings = 1000;
    double contactThreshold_n = 0.01;
};

struct ProcedureStep {
    double displacement_m = 0.0;         // the step's nominal displacement
    std::size_t available = 0;           // samples at this step
    std::optional<StepReading> reading;  // none: short
};

struct StepProcedureReading {
    std::vector<ProcedureStep> steps;  // by displacement
    // Over the steps read in range: the mean k_o, and the standard error of
    // that mean from the steps' scatter (two steps at least).
    std::optional<double> stiffness_n_per_m;
    std::optional<double> standardError_n_per_m;
    std::size_t stepsInRange = 0;
};

// Spans of equal length; throws std::invalid_argument when they differ.
StepProcedureReading readSteps(const sensors::CompliancePair& pair, std::span<const double> displacement_m,
                               std::span<const double> forceHigh_n, std::span<const double> forceLow_n,
                               const StepSettings& settings = {});

}  // namespace tactiscope::core::compliance
