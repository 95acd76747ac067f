// How far a cantilever's small-deflection (linear) model can be believed:
// the large-deflection elastica of a beam with a tip force that stays
// perpendicular to the unloaded beam, integrated along the arc with the
// beam's bending stiffness EI(s), against the linear tip deflection.
//   dθ/ds = F·(x_tip − x(s)) / EI(s),  dx/ds = cos θ,  dy/ds = sin θ,
//   θ(0) = 0, and x_tip found by iterating the shape (shooting).
// Linear: w = ∫ θ_lin ds with dθ_lin/ds = F·(l − s)/EI(s). The linear
// model overstates the tip deflection, and understates the lever arm, by
// the error this gives; the capacitive beam's readings (seed 002, eqs.
// 11–13 and 28) rest on it, so its limits come from here.
// Checked against the classical tip-loaded uniform cantilever (Bisshopp &
// Drucker 1945): at F·l²/EI = 1 the tip deflects 0.3017·l, not l/3.
#pragma once

#include "core/sensors/CapacitiveBeam.h"

#include <functional>

namespace tactiscope::core::sensors {

// Bending stiffness EI at arc length s from the clamp, in N·m².
using BendingStiffness = std::function<double(double s_m)>;

struct TipDeflection {
    double linear_m = 0.0;  // the small-deflection model's
    double exact_m = 0.0;   // the elastica's
    // How much the linear model overstates it: linear/exact − 1.
    double modelError() const { return linear_m / exact_m - 1.0; }
};

// Throws std::invalid_argument for a length or force that is not positive
// and finite.
TipDeflection tipDeflection(const BendingStiffness& stiffness, double length_m, double force_n);

// The uniform-strength beam's EI(s): segment 1 tapers, A₁·b·(l − s)/l;
// segment 2 is A₂·(1 − α)·b (CapacitiveBeam.h).
BendingStiffness bendingStiffness(const CapacitiveBeam& beam);

// The tip force at which the linear model overstates the tip deflection by
// `error` (e.g. 0.02), by bisection on the elastica. Throws
// std::invalid_argument for an error outside (0, 0.5).
double forceAtModelError(const BendingStiffness& stiffness, double length_m, double error);

}  // namespace tactiscope::core::sensors
