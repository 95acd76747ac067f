// Shunt calibration of a strain-gauge bridge (issue 39): a known resistor
// R_s switched across the first active gauge (resistance R_g, as every arm)
// lowers that arm to R_g·R_s/(R_g + R_s), a relative change
//   y = −R_g/(R_g + R_s)
// of that one arm, whatever the bridge. The bridge then gives
// V_r = y/(4 + 2y), which the channel reads through its bridge type's
// conversion (StrainGaugeChain) as the strain it would show:
//   quarter:          ε = y/GF                 (its conversion inverts V_r exactly)
//   half, bending:    ε = y/((2 + y)·GF)       (≈ half the quarter's)
//   full, bending:    ε = y/((4 + 2y)·GF)      (≈ a quarter of it)
// Dimensionless throughout (Ω/Ω). Comparing that with the step a shunt
// makes in the measured strain checks the gauge factor, the excitation, the
// gain and the bridge's wiring in one go.
#pragma once

#include "core/straingauge/StrainGaugeChain.h"

#include <span>

namespace tactiscope::core::straingauge {

// The strain a channel of this bridge shows with the shunt on (negative: a
// shunt lowers the arm). Throws std::invalid_argument for resistances or a
// gauge factor that are not positive and finite.
double shuntStrain(BridgeType type, double gaugeResistance_ohm, double shuntResistance_ohm, double gaugeFactor);

struct ShuntCheck {
    double expected = 0.0;   // strain
    double measured = 0.0;   // the step the shunt made
    double deviation = 0.0;  // (measured − expected)/expected
    bool passed = false;     // |deviation| ≤ the tolerance
};

// `tolerance`: the largest relative deviation that passes (0.01: 1 %).
ShuntCheck checkShunt(double expected, double measured, double tolerance);

// The step a shunt made in a channel: the mean of the samples with it on
// less the mean of those before, and that difference's standard
// uncertainty, √(s²_on/n_on + s²_off/n_off) (white noise). Throws
// std::invalid_argument for fewer than two samples either way.
struct ShuntStep {
    double step = 0.0;
    double uncertainty = 0.0;
};
ShuntStep measureShuntStep(std::span<const double> off, std::span<const double> on);

// The number of active gauges of a bridge type (quarter 1, half 2, full 4):
// how calibration records keep a bridge, a physical count rather than a code.
int activeGauges(BridgeType type);

}  // namespace tactiscope::core::straingauge
