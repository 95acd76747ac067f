// ModeChoice: the bar's mode asked of the station, the device's shown, roles set.
#include "ui/live/ModeChoice.h"

#include "core/ModeCapability.h"
#include "devices/session/LiveSession.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/VocabularyText.h"
#include "ui/device/ChannelRolesBox.h"
#include "ui/device/DevicePanel.h"
#include "ui/live/LiveStation.h"
#include "ui/live/LiveTraces.h"
#include "ui/live/ModeViews.h"
#include "ui/live/SessionBar.h"
#include "ui/plot/ModeXY.h"
#include "ui/plot/XYPlotWidget.h"

#include <QDockWidget>
#include <QSignalBlocker>
#include <QTimer>
#include <QWidget>

namespace tactiscope::ui {

ModeChoice::ModeChoice(LiveStation& station, Widgets widgets, std::function<void(const QString&)> tell, QWidget* window)
    : QObject(window),
      m_station(station),
      m_widgets(widgets),
      m_tell(std::move(tell)),
      m_window(window)
{
    connect(widgets.bar, &SessionBar::modeChanged, this, &ModeChoice::chosen);
    connect(widgets.panel->rolesBox(), &ChannelRolesBox::rolesChosen, this, &ModeChoice::setRoles);
    connect(&station, &LiveStation::connected, this, &ModeChoice::connected);
    connect(&station, &LiveStation::disconnected, this, &ModeChoice::showView);
}

bool ModeChoice::setMode(core::Mode mode)
{
    m_widgets.bar->setMode(mode);  // chosen() asks the station
    return m_widgets.bar->metadata().mode == mode;
}

void ModeChoice::showMode(core::Mode mode)
{
    m_widgets.views->bind(m_station.device(), mode);
    showView();
}

void ModeChoice::showView()
{
    const auto shown = m_widgets.views->show(m_station.device(), m_widgets.bar->metadata().mode);
    m_widgets.xyDock->setWindowTitle(showModeXY(*m_widgets.xy, m_station.device(), shown));
}

// A mode the device cannot feed is refused here, before anything is
// recorded: the bar goes back to the device's mode and says why.
void ModeChoice::chosen()
{
    const core::Mode mode = m_widgets.bar->metadata().mode;
    if (const auto refusal = m_station.setMode(mode)) {
        const auto& live = *m_station.device();
        const QSignalBlocker quiet(m_widgets.bar);
        m_widgets.bar->setMode(live.mode());
        const auto unitless = core::channelsWithoutFittingUnit(mode, live.channels());
        const QString how =
            unitless.empty()
                ? tr("Give the device's channels roles in the device panel (Channel roles: %1), or connect the "
                     "probe made for %2.")
                      .arg(QString::fromStdString(core::roleExample(mode, live.channels()))
                               .replace(QLatin1Char(','), QStringLiteral(", ")),
                           modeTitle(mode))
                : tr("Give %1 its unit: in the device panel's Units before connecting (%1=µε), by a label on "
                     "the board (%1[µε]:12.5), or, for ADC counts, by the sensor profile's channel scale.")
                      .arg(QString::fromStdString(unitless.front()));
        reportProblem(m_window,
                      {tr("Mode not available"),
                       tr("%1 cannot run on %2.").arg(modeTitle(mode), QString::fromStdString(live.source().name())),
                       *refusal, tr("The session stays in %1. %2").arg(modeTitle(live.mode()), how),
                       QStringLiteral("modeRefusedBox")});
    }
    showView();
}

// The bar shows the mode the device runs (its own wins).
void ModeChoice::connected()
{
    auto& live = *m_station.device();
    reportAnalysisProblems(m_window, live.takeProblems());
    if (live.mode() != m_widgets.bar->metadata().mode) {
        const QSignalBlocker quiet(m_widgets.bar);
        m_widgets.bar->setMode(live.mode());
        // Told once the window is up: a message shown while it is hidden
        // leaves the status bar's device label drawn underneath it.
        const QString told =
            tr("Mode: %1, the mode of %2").arg(modeTitle(live.mode()), QString::fromStdString(live.source().name()));
        QTimer::singleShot(0, this, [this, told] { m_tell(told); });
    }
    showView();
}

// Roles chosen in the device panel: the processors are rebuilt on them and
// the bar's mode runs when it now can; the choice is kept for the device.
void ModeChoice::setRoles(const core::RoleAssignment& roles)
{
    auto* live = m_station.device();
    if (!live) return;
    if (const auto refusal = m_station.setRoles(roles)) {
        reportProblem(m_window, {tr("Roles not changed"), tr("The channels keep their roles."), *refusal, {}});
        m_widgets.panel->showRoles(*live);
        return;
    }
    reportAnalysisProblems(m_window, live->takeProblems());
    {
        const QSignalBlocker quiet(m_widgets.bar);
        m_widgets.bar->setMode(live->mode());
    }
    m_widgets.views->bindAll(live);
    m_widgets.traces->showChannels();
    showView();
    m_tell(tr("Channel roles set: %1 runs on %2")
               .arg(modeTitle(live->mode()), QString::fromStdString(live->source().name())));
}

}  // namespace tactiscope::ui
