// Hysteresis rule for live autoscaling.
#include "ui/plot/AxisAutoRange.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {

AxisRange nextAxisRange(AxisRange current, double dataMin, double dataMax)
{
    double span = dataMax - dataMin;
    if (!(span > 0.0)) span = std::max(std::abs(dataMax), 1.0) * 1e-3;
    const bool unset = !(current.size() > 0.0);
    const bool outside = dataMin < current.lower || dataMax > current.upper;
    const bool tooLoose = span < current.size() / 3.0;
    if (!unset && !outside && !tooLoose) return current;
    const double centre = 0.5 * (dataMin + dataMax);
    const double half = 0.5 * span * 1.2;
    return {centre - half, centre + half};
}

}  // namespace tactiscope::ui
