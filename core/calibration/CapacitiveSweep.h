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
// A beam lags a sweep (the soft beam settles in about 0.4 s): it reads low
// while loading and high while unloading, by the force the sweep moves in
// that time, several per cent of full scale at a brisk pace — a property
// of the pace, not of the beam's static sensitivity. The beam is taken to
// settle as a first-order lag; the time constant that puts loading and
// unloading on one line (the least scatter about it, within maxLag_s) is
// found, stated, and the reference passed through it before binning. What
// stays apart is the silicone's own hysteresis (its slow creep), as weights
// show it; a lag from the two devices' clocks is taken out with it.
#pragma once

#include "core/calibration/CapacitiveSteps.h"

#include <cstddef>

namespace tactiscope::core::calibration {

struct SweepSettings {
    std::size_t bins = 10;             // per direction, over the sweep's force span
    std::size_t minimumPerBin = 5;     // samples a bin needs to give a point
    double unloadedFraction = 0.02;    // of the span: at or below it, the beam is unloaded
    double turnFraction = 0.05;        // of the span: a turn of the sweep
    double maxLag_s = 3.0;             // the beam's time constant looked for; 0: none taken out
    StabilitySettings stability = {};  // the baselines' (capacitiveStabilityDefaults)
};

struct SweepSteps {
    CapacitiveSteps steps;         // the calibration's input and the points, as for weights
    double referenceZero_n = 0.0;  // the reference's mean over the unloaded start, taken off
    double span_n = 0.0;           // the largest reference force, from that zero
    std::size_t turns = 0;         // the sweep's turning points (1: up once, then down)
    double lag_s = 0.0;            // the beam's time constant, taken out
    std::size_t samplesUsed = 0;   // loaded samples in a bin that gave a point
};

// `recording` needs every sample's time and reference force (load_n, as
// read: its zero is found here). Throws std::invalid_argument for a
// recording without them, whose reference does not change, that does not
// start unloaded or whose start never settles, or with fewer than two
// points.
SweepSteps stepsFromSweep(const CapacitiveRecording& recording, const SweepSettings& settings);

}  // namespace tactiscope::core::calibration
