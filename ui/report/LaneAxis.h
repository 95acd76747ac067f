// A lane's value axis as both session plots (the review's and the
// report's) draw it: the title over the unit, few ticks as a lane is low,
// named levels for a quantity that takes a few values (the detector's
// decision), the threshold a quantity is read against as a dashed line,
// and a value range that keeps the data and the threshold in view.
#pragma once

#include "ui/common/DisplayUnits.h"

#include <optional>

class QCPAxis;
class QCPAxisRect;
class QCPRange;
class QCustomPlot;

namespace tactiscope::ui {

void setUpLaneAxis(QCPAxisRect& lane, const DisplayUnit& unit, std::optional<double> threshold_si);
// `shown`: the data's extent in display units, when there is any.
void fitLaneRange(QCPAxis& values, const DisplayUnit& unit, std::optional<QCPRange> shown,
                  std::optional<double> threshold_si);

}  // namespace tactiscope::ui
