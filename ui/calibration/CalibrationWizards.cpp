// CalibrationWizards: which wizard a mode calibrates with.
#include "ui/calibration/CalibrationWizards.h"

#include "ui/calibration/CapacitiveWizard.h"
#include "ui/calibration/GaugeFactorWizard.h"

namespace tactiscope::ui {

QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored)
{
    QWizard* wizard = nullptr;
    const auto report = [stored](std::int64_t, const QString& sensor) { stored(sensor); };
    switch (mode) {
    case core::Mode::PanelScan:
        return nullptr;
    case core::Mode::Palpation: {
        auto* gauge = new GaugeFactorWizard(std::move(context), parent);
        QObject::connect(gauge, &GaugeFactorWizard::calibrationStored, parent, report);
        wizard = gauge;
        break;
    }
    case core::Mode::Capacitive: {
        auto* capacitive = new CapacitiveWizard(std::move(context), parent);
        QObject::connect(capacitive, &CapacitiveWizard::calibrationStored, parent, report);
        wizard = capacitive;
        break;
    }
    }
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
    return wizard;
}

}  // namespace tactiscope::ui
