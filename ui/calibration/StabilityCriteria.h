// The settable meaning of "stable" for a calibration step: a window length
// and the largest drift and scatter allowed in it, shown in the channel's
// display unit and handed out in the channel's own unit.
#pragma once

#include "core/calibration/StabilityMonitor.h"
#include "ui/common/DisplayUnits.h"

#include <QWidget>

class QDoubleSpinBox;

namespace tactiscope::ui {

class StabilityCriteria : public QWidget {
    Q_OBJECT

public:
    StabilityCriteria(const DisplayUnit& unit, QWidget* parent = nullptr);

    core::calibration::StabilitySettings settings() const;
    void setSettings(const core::calibration::StabilitySettings& settings);

signals:
    void edited();

private:
    DisplayUnit m_unit;
    QDoubleSpinBox* m_window;
    QDoubleSpinBox* m_maxDrift;
    QDoubleSpinBox* m_maxNoise;
};

}  // namespace tactiscope::ui
