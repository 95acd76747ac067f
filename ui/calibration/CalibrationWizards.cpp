// CalibrationWizards: which wizard a mode calibrates with.
#include "ui/calibration/CalibrationWizards.h"

#include "ui/calibration/CapacitiveWizard.h"
#include "ui/calibration/GaugeFactorWizard.h"

namespace tactiscope::ui {

QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored)
{
    // The modes that read a stored calibration, and their wizards.
    CalibrationWizard* wizard = nullptr;
    if (mode == core::Mode::Palpation) wizard = new GaugeFactorWizard(std::move(context), parent);
    if (mode == core::Mode::Capacitive) wizard = new CapacitiveWizard(std::move(context), parent);
    if (!wizard) return nullptr;
    QObject::connect(wizard, &CalibrationWizard::calibrationStored, parent,
                     [stored](std::int64_t, const QString& sensor) { stored(sensor); });
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
    return wizard;
}

}  // namespace tactiscope::ui
