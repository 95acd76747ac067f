// CalibrationWizards: which wizard a mode calibrates with.
#include "ui/calibration/CalibrationWizards.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/calibration/CalibrationHistory.h"
#include "ui/calibration/CalibrationWizard.h"
#include "ui/calibration/ShuntCheckDialog.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/VocabularyText.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/ModeUi.h"

#include <QMenu>

namespace tactiscope::ui {
namespace {

// The station's devices beside `calibrated`, each read while it stays in
// the session (a wizard may outlive its place there).
std::vector<ReferenceDevice> otherDevices(const LiveStation& station, const devices::session::LiveSession* calibrated)
{
    std::vector<ReferenceDevice> result;
    const auto& pipeline = station.pipeline();
    for (std::size_t i = 0; i < pipeline.size(); ++i) {
        const auto& live = pipeline.device(i);
        if (&live == calibrated) continue;
        auto stillThere = [station = &station, device = &live] {
            const auto& now = station->pipeline();
            for (std::size_t j = 0; j < now.size(); ++j)
                if (&now.device(j) == device) return true;
            return false;
        };
        result.push_back(
            {QString::fromStdString(pipeline.name(i)), QString::fromStdString(live.source().name()), live.channels(),
             live.buffer(), live.source().nominalSampleRate_hz(),
             [stillThere, device = &live] { return stillThere() ? device->source().hostClock() : std::nullopt; }});
    }
    return result;
}

}  // namespace

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

void calibrateLive(LiveStation& station, core::Mode mode, LiveCalibration setup, QWidget* window)
{
    auto* live = station.device();
    if (!live) return setup.tell(QObject::tr("Connect the probe to calibrate (or the simulator's calibration rig)."));
    if (station.isRecording())
        return setup.tell(QObject::tr("Stop recording first: a session keeps the calibration it started with."));
    CalibrationContext context{
        live->buffer(), live->channels(), live->source().nominalSampleRate_hz(), station.loadRig(), setup.store,
        setup.operatorName, setup.profileDirectory,
        // The device's clock while it is the station's (a wizard may outlive it).
        [station = &station, live] { return station->device() == live ? live->source().hostClock() : std::nullopt; },
        [station = &station, live] { return otherDevices(*station, live); }};
    openCalibrationWizard(mode, std::move(context), window, [&station, mode, setup, window](const QString& sensor) {
        auto* now = station.device();
        if (!now) return;
        const QString view = modeTitle(mode).toLower();
        if (const auto problem = now->reloadCalibrations(mode))
            reportProblem(window, {QObject::tr("Calibration not applied"),
                                   QObject::tr("The %1 view does not read through the new calibration.").arg(view),
                                   QString::fromStdString(*problem),
                                   {}});
        reportAnalysisProblems(window, now->takeProblems());
        setup.applied(mode);
        // The zero in use was taken before this calibration: readings through
        // it are off by what the probe drifted since, until a tare.
        const bool hasZero = core::definitionOf(mode).noZero.empty();
        setup.tell(hasZero ? QObject::tr("Calibration of %1 stored; the %2 view reads through it. Tare (Ctrl+T) with "
                                         "the probe unloaded: the zero in use was taken before it.")
                                 .arg(sensor, view)
                           : QObject::tr("Calibration of %1 stored; the %2 view reads through it.").arg(sensor, view));
    });
}

void addCalibrationActions(QMenu* tools, LiveStation& station, std::function<LiveCalibration()> setup, QWidget* window)
{
    for (const auto& definition : core::modeDefinitions())
        if (const auto action = modeUi(definition.mode).calibrateAction)
            tools->addAction(action(), window, [&station, setup, window, mode = definition.mode] {
                calibrateLive(station, mode, setup(), window);
            });
    QAction* shunt = tools->addAction(QObject::tr("Sh&unt check…"), window, [&station, setup, window] {
        if (!station.device()) return setup().tell(QObject::tr("Connect a probe to check its bridges."));
        const auto now = setup();
        auto* dialog =
            new ShuntCheckDialog({[&station] { return station.device(); }, now.storePath, now.operatorName}, window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    shunt->setObjectName(QStringLiteral("shuntCheckAction"));
    tools->addAction(QObject::tr("Calibration &history…"), window, [setup, window] {
        auto* history = new CalibrationHistory(setup().storePath, window);
        history->setAttribute(Qt::WA_DeleteOnClose);
        history->show();
    });
}

}  // namespace tactiscope::ui
