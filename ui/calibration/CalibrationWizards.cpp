// CalibrationWizards: which wizard a mode calibrates with.
#include "ui/calibration/CalibrationWizards.h"

#include "ui/calibration/CapacitiveWizard.h"
#include "ui/calibration/GaugeFactorWizard.h"

namespace tactiscope::ui {

QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored)
{
    CalibrationWizard* wizard = nullptr;
    switch (mode) {
    case core::Mode::PanelScan:
    case core::Mode::General:
        return nullptr;
    case core::Mode::Palpation:
        wizard = new GaugeFactorWizard(std::move(context), parent);
        break;
    case core::Mode::Capacitive:
        wizard = new CapacitiveWizard(std::move(context), parent);
        break;
    }
    QObject::connect(wizard, &CalibrationWizard::calibrationStored, parent,
                     [stored](std::int64_t, const QString& sensor) { stored(sensor); });
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
    return wizard;
}

}  // namespace tactiscope::ui
