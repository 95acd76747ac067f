// The one compliance probe of the simulated world (seed 001's Perspex pair,
// 50 × 10 mm, 3 mm and 1 mm thick, 3 GPa): the palpation phantom is pressed
// with it and the gauge-factor rig clamps its beams, so calibrating on the
// rig and then palpating reads the phantom's true stiffness.
//
// Its gauges are of one batch whose true factor is 7 % above the
// datasheet's 2.0 that the chain is configured with. Uncalibrated, both
// forces read 7 % high and kₒ, which needs only their ratio, is exact;
// with one beam calibrated the ratio mixes a true and a nominal factor
// (the live view says so); with both calibrated forces and kₒ are true.
#pragma once

#include "core/sensors/CantileverBeam.h"

namespace tactiscope::devices::simulator {

inline constexpr core::sensors::CantileverGeometry kProbeStiffBeam{0.05, 0.01, 0.003, 3e9};
inline constexpr core::sensors::CantileverGeometry kProbeSoftBeam{0.05, 0.01, 0.001, 3e9};
inline constexpr double kProbeTrueGaugeFactor = 2.14;

}  // namespace tactiscope::devices::simulator
