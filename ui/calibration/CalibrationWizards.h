// Opening the calibration wizard of a mode whose processor reads a stored
// calibration (its ui entry names the wizard: palpation's gauge factor, the
// capacitive beam's C0 and sensitivity), on the live station's device.
#pragma once

#include "core/Vocabulary.h"
#include "ui/calibration/CalibrationContext.h"

#include <QString>

#include <functional>
#include <memory>

class QMenu;
class QWidget;
class QWizard;

namespace tactiscope::ui {

class LiveStation;

// Opens the wizard of `mode` (non-modal, deleted when closed); `stored` gets
// the sensor's name each time it stores a calibration. Null for a mode
// without one.
QWizard* openCalibrationWizard(core::Mode mode, CalibrationContext context, QWidget* parent,
                               std::function<void(const QString& sensor)> stored);

// The wizard of `mode` on the station's window device. Refused, with a
// line told, with no device or while recording (a session keeps the
// calibration it started with). Each calibration stored is read through at
// once by the device's processor (a refusal is shown); then `applied` lets
// the mode's views show it, and the operator is told what the new
// calibration asks: a tare, unloaded, for a mode with a zero (the zero in
// use was taken before it).
struct LiveCalibration {
    QString storePath;  // the shunt check's and the calibration history's
    std::shared_ptr<core::storage::StoreWorker> store;
    QString operatorName;
    QString profileDirectory;
    std::function<void(const QString&)> tell;  // a line in the status bar
    std::function<void(core::Mode)> applied;   // the mode's views read through it
};
void calibrateLive(LiveStation& station, core::Mode mode, LiveCalibration setup, QWidget* window);
// The Tools menu's calibration entries: each mode's wizard (ui/modes/ModeUi.h)
// on the station's device, the shunt check of its bridges and the
// calibration history, with the setup asked at each use.
void addCalibrationActions(QMenu* tools, LiveStation& station, std::function<LiveCalibration()> setup, QWidget* window);

}  // namespace tactiscope::ui
