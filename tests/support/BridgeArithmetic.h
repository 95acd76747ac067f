// A half bridge's counts per newton at a beam's root, from the bridge's
// arithmetic (in bending V/V_exc = GF·ε/2) and the beam's root strain per
// newton 6L/(E·w·t²): what a maker writes in a profile's channel scale for
// a board that prints the simulated probe's raw counts, worked out apart
// from the code under test.
#pragma once

#include "core/sensors/CantileverBeam.h"
#include "devices/simulator/PalpationScenario.h"

#include <cmath>

namespace tactiscope::testing {

inline double countsPerNewton(const core::sensors::CantileverGeometry& beam,
                              const devices::simulator::PalpationParameters& p)
{
    const double strainPerNewton =
        6.0 * beam.length_m / (beam.youngsModulus_pa * beam.width_m * beam.thickness_m * beam.thickness_m);
    return p.trueGaugeFactor / 2.0 * strainPerNewton * p.bridge.excitation_v * p.adc.gain / p.adc.reference_v *
           std::ldexp(1.0, p.adc.bits - 1);
}

}  // namespace tactiscope::testing
