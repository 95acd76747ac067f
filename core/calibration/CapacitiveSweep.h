// A capacitive beam calibrated against a reference force (issue 40): a
// load cell in series with the beam reads the force of a continuous
// loading sweep, and each capacitance sample is paired with the reference
// at its instant. The sweep becomes the same calibration input as weights
// (core/calibration/CapacitiveSteps), so the fit, its ± and the history
// are the weights' own:
//
// - the unloaded stretch before the sweep gives C0 and its noise (from its
//   first stable window on) and the reference's own zero, taken off every
//   reference value; the unloaded stretch after it, the drift;
// - the sweep is split where it turns (a rise or a fall of 5 % of its
//   span past the last extreme) into loading and unloading;
// - each direction's samples are gathered in force bins of equal width,
//   and a bin's point is its capacitance at the bin's middle force (a line
//   through the bin's samples), so loading and unloading meet at the same
//   loads and give the hysteresis as weights placed and removed do.
//
// A beam that lags the sweep (the soft silicone settling, its creep) reads
// low while loading and high while unloading: the points' scatter, and so
// the slope's ±, carries it, and the hysteresis shows it.
#pragma once

#include "core/calibration/CapacitiveSteps.h"

#include <cstddef>

namespace tactiscope::core::calibration {

struct SweepSettings {
    std::size_t bins = 10;             // per direction, over the sweep's force span
    std::size_t minimumPerBin = 5;     // samples a bin needs to give a point
    double unloadedFraction = 0.02;    // of the span: at or below it, the beam is unloaded
    double turnFraction = 0.05;        // of the span: a turn of the sweep
    StabilitySettings stability = {};  // the baselines' (capacitiveStabilityDefaults)
};

struct SweepSteps {
    CapacitiveSteps steps;         // the calibration's input and the points, as for weights
    double referenceZero_n = 0.0;  // the reference's mean over the unloaded start, taken off
    double span_n = 0.0;           // the largest reference force, from that zero
    std::size_t turns = 0;         // the sweep's turning points (1: up once, then down)
    std::size_t samplesUsed = 0;   // loaded samples in a bin that gave a point
};

// `recording` needs every sample's time and reference force (load_n, as
// read: its zero is found here). Throws std::invalid_argument for a
// recording without them, whose reference does not change, that does not
// start unloaded or whose start never settles, or with fewer than two
// points.
SweepSteps stepsFromSweep(const CapacitiveRecording& recording, const SweepSettings& settings);

}  // namespace tactiscope::core::calibration
