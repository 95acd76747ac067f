// A surface-deflection event: a run of samples with the same non-zero
// detector decision, e.g. "defect at 12.40–12.47 s, A then B, peak R 0.97 at
// a lag of 46 ms, i.e. 326 mm/s".
#pragma once

#include <optional>

namespace tactiscope::core::detector {

struct DefectEvent {
    double start_s = 0.0;  // time of the first sample of the run
    double end_s = 0.0;    // time of the last sample of the run
    int direction = 0;     // +1: A then B; −1: B then A
    double peakR = 0.0;    // largest R of the event's direction
    double peakLag_s = 0.0;
    // Cantilever spacing / lag at the peak, when the spacing is known.
    std::optional<double> speed_m_per_s;
    // Where the rig's position channel had the probe when its centre passed
    // the dent (core/detector/PositionTrail.h); none without one.
    std::optional<double> position_m;
};

}  // namespace tactiscope::core::detector
