// A capacitive beam's samples paired with a reference force at their
// instants (issue 40), both already on one time axis: the reference is
// interpolated linearly between its own samples, and nothing is made up
// across a gap in it (two of its periods) or beyond its ends. Also its
// steepest change, which turns a timing uncertainty into a force one.
#pragma once

#include "core/calibration/CapacitiveSteps.h"

#include <cstddef>
#include <span>

namespace tactiscope::core::calibration {

struct PairedSweep {
    CapacitiveRecording recording;  // the beam's times, its capacitance and the force there
    std::size_t outsideReference = 0;
    double steepest_n_per_s = 0.0;  // between means of consecutive half seconds of the reference
};

// Times ascending; NaN samples (gaps) are left out. Throws
// std::invalid_argument for unequal lengths, a rate that is not positive,
// or fewer than three beam samples with a force.
PairedSweep pairWithReference(std::span<const double> beam_t_s, std::span<const double> capacitance_f,
                              std::span<const double> reference_t_s, std::span<const double> force_n,
                              double referenceRate_hz);

}  // namespace tactiscope::core::calibration
