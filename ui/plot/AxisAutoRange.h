// Calm autoscaling for a live axis: grow at once when the data leaves the
// range, shrink only when the data has clearly become smaller, so the axis
// does not twitch with every frame's noise.
#pragma once

namespace tactiscope::ui {

struct AxisRange {
    double lower = 0.0;
    double upper = 1.0;
    double size() const { return upper - lower; }
};

// Returns the range to show for data spanning [dataMin, dataMax], given the
// range shown now. The result keeps a margin of 10% of the data span on each
// side; it is recomputed only if the data leaves the current range or fills
// less than a third of it, or the current range is empty (nothing shown
// yet). A flat signal gets a small span around its value.
AxisRange nextAxisRange(AxisRange current, double dataMin, double dataMax);

}  // namespace tactiscope::ui
