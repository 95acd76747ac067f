// CalibrationWizards: which wizard a mode calibrates with.
#include "ui/calibration/CalibrationWizards.h"

#include "ui/calibration/CalibrationWizard.h"
#include "ui/modes/ModeUi.h"

namespace tactiscope::ui {

QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored)
{
    // The modes that read a stored calibration have a wizard (ui/modes/ModeUi.h).
    const auto make = modeUi(mode).calibrationWizard;
    if (!make) return nullptr;
    CalibrationWizard* wizard = make(std::move(context), parent);
    QObject::connect(wizard, &CalibrationWizard::calibrationStored, parent,
                     [stored](std::int64_t, const QString& sensor) { stored(sensor); });
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
    return wizard;
}

}  // namespace tactiscope::ui
