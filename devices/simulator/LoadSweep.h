// A continuous calibration sweep (issue 40): the force a rig pushes a
// capacitive beam and a load cell in series with, rising linearly from
// nothing to its peak and back, once or several times. Two emulators given
// one start instant feel one force at every instant of the host's clock,
// so the beam can be calibrated against the load cell's reading of it.
#pragma once

#include "core/calibration/CapacitiveCalibration.h"

#include <cmath>

namespace tactiscope::devices::simulator {

struct LoadSweep {
    double peak_n = 150.0 * core::calibration::kMilligramForce_n;  // the heaviest of the weights' set
    double ramp_s = 20.0;                                          // each way
    int cycles = 1;

    double duration_s() const { return 2.0 * ramp_s * cycles; }
    // The force `since_s` after the sweep began: nothing before and after.
    double load_n(double since_s) const
    {
        if (since_s <= 0.0 || since_s >= duration_s()) return 0.0;
        const double phase = std::fmod(since_s, 2.0 * ramp_s) / ramp_s;
        return peak_n * (phase < 1.0 ? phase : 2.0 - phase);
    }
};

}  // namespace tactiscope::devices::simulator
