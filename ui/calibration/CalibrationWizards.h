// Opening the calibration wizard of a mode whose processor reads a stored
// calibration (its ui entry names the wizard: palpation's gauge factor, the
// capacitive beam's C0 and sensitivity).
#pragma once

#include "core/Vocabulary.h"
#include "ui/calibration/CalibrationContext.h"

#include <QString>

#include <functional>

class QWidget;
class QWizard;

namespace tactiscope::ui {

// Opens the wizard of `mode` (non-modal, deleted when closed); `stored` gets
// the sensor's name each time it stores a calibration. Null for a mode
// without one.
QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored);

}  // namespace tactiscope::ui
