// One calibration reading taken as a careful operator takes it: wait until
// the signal is stable (a StabilityMonitor window passes its drift and
// noise limits), then average a fresh window of the same length that must
// pass too, and keep that one.
//
// Why a fresh window: the first window found stable still holds the tail
// of the swing to the new load at its start. A first-order settling leaves
// a residue there that a line's slope over the whole window barely shows,
// and it pulls every point toward the load before it, so the fitted slope
// is biased by more than the points' scatter can tell (seen on the gauge
// rig: a gauge factor whose ± covered the truth in 0 % of runs). The fresh
// window starts one window later, when that residue has decayed by another
// factor exp(−window/τ).
//
// The wizards (through ui::StabilityWatch) and the coverage tests use this
// one rule.
#pragma once

#include "core/calibration/StabilityMonitor.h"

#include <cstddef>
#include <optional>
#include <span>

namespace tactiscope::core::calibration {

class SettledCapture {
public:
    enum class Phase {
        Watching,   // not armed: windows are judged for display only
        Settling,   // armed, waiting for the first stable window
        Averaging,  // filling the fresh window that is kept
    };

    // Throws std::invalid_argument for bad settings (as StabilityMonitor).
    explicit SettledCapture(StabilitySettings settings);

    void add(double t_s, double value) { m_monitor.add(t_s, value); }
    // Judges the samples added so far (call once per batch: each judgement
    // fits a line through the whole window). When armed, returns the kept
    // window once, when the fresh window is full and stable, and goes back
    // to watching; a fresh window that is not stable sends the capture back
    // to settling.
    std::optional<WindowStatistics> judge();
    // Drops the samples so far and waits for a stable window of samples
    // added from now on (a new load was placed).
    void arm();
    void disarm() { m_phase = Phase::Watching; }
    // Drops the samples so far, keeping the phase (samples were lost: a
    // window must be contiguous).
    void restart();

    Phase phase() const { return m_phase; }
    // The newest full window, for an indicator; none while one fills.
    const std::optional<WindowStatistics>& latest() const { return m_latest; }

private:
    StabilityMonitor m_monitor;
    Phase m_phase = Phase::Watching;
    std::optional<WindowStatistics> m_latest;
};

// The same rule on a recorded series: the index of the first sample of the
// fresh window it keeps (the settled part begins there), judged after every
// sample as a live reading is judged after every batch; none when the
// series never settles so.
std::optional<std::size_t> settledFrom(std::span<const double> t_s, std::span<const double> values,
                                       const StabilitySettings& settings);

}  // namespace tactiscope::core::calibration
