// A one-line light for a StabilityWatch: grey while there is no signal or
// a window is still filling, amber while the signal settles (with the drift
// and noise against their limits, so the user sees what it waits for),
// green with the window's mean and σ once it is stable.
#pragma once

#include "ui/common/DisplayUnits.h"

#include <QLabel>

namespace tactiscope::ui {

class StabilityWatch;

class StabilityIndicator : public QLabel {
    Q_OBJECT

public:
    // Values are shown in `unit` (scale applied to the channel's values).
    StabilityIndicator(const StabilityWatch* watch, QWidget* parent = nullptr);
    void setUnit(const DisplayUnit& unit);

private:
    void refresh();

    const StabilityWatch* m_watch;
    DisplayUnit m_unit;
};

}  // namespace tactiscope::ui
