// LiveProfiles: the dialog, its lock while recording, a profile into the live device.
#include "ui/profiles/LiveProfiles.h"

#include "devices/session/LiveSession.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/VocabularyText.h"
#include "ui/live/LiveStation.h"
#include "ui/profiles/ActiveProfiles.h"
#include "ui/profiles/ProfileLibrary.h"
#include "ui/profiles/SensorProfileDialog.h"

namespace tactiscope::ui {

LiveProfiles::LiveProfiles(LiveStation& station, Hooks hooks, QWidget* window)
    : QObject(window),
      m_station(station),
      m_hooks(std::move(hooks)),
      m_window(window)
{
    connect(&station, &LiveStation::recordingChanged, this, &LiveProfiles::lock);
}

SensorProfileDialog* LiveProfiles::show()
{
    if (!m_dialog) {
        m_dialog = new SensorProfileDialog(ProfileLibrary::defaultDirectory(), m_window);
        connect(m_dialog, &SensorProfileDialog::activeProfileChanged, this, &LiveProfiles::apply);
        lock();
    }
    if (!m_dialog->hasUnsavedChanges()) m_dialog->setMode(wordText(m_hooks.mode()));
    m_dialog->show();
    m_dialog->raise();
    m_dialog->activateWindow();
    return m_dialog;
}

void LiveProfiles::lock()
{
    if (m_dialog) m_dialog->setLocked(m_station.isRecording(), tr("fixed while recording: a session keeps one sensor"));
}

void LiveProfiles::apply(const QString& modeName)
{
    const auto mode = core::modeFromString(modeName.toStdString());
    auto* live = m_station.device();
    if (!live || !mode) return;  // the next connection reads it
    ActiveProfile active = activeProfile(modeName);
    if (!active.error.isEmpty()) reportProblem(m_window, badProfile(modeName, active.error));
    if (const auto refusal = live->setProfile(*mode, std::move(active.profile))) {
        reportProblem(m_window,
                      {tr("Bad profile"), tr("The %1 probe was not changed.").arg(modeName),
                       QString::fromStdString(*refusal), tr("Fix the profile in Session ▸ Sensor profiles.")});
        return;
    }
    m_hooks.applied(*mode);
    if (live->unit(*mode))
        m_hooks.tell(tr("New %1 profile: its factors apply to the zero in use").arg(modeTitle(*mode)));
}

}  // namespace tactiscope::ui
