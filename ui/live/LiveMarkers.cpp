// LiveMarkers: a marker now, or with its note, into the recording or its session.
#include "ui/live/LiveMarkers.h"

#include "core/storage/StoreWorker.h"
#include "devices/session/LiveSession.h"
#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/live/LiveStation.h"
#include "ui/live/LiveTraces.h"
#include "ui/live/MarkerNote.h"

#include <QWidget>

namespace tactiscope::ui {

LiveMarkers::LiveMarkers(LiveStation& station, LiveTraces& traces, Hooks hooks, QWidget* window)
    : QObject(window),
      m_station(station),
      m_traces(traces),
      m_hooks(std::move(hooks)),
      m_window(window)
{
}

void LiveMarkers::mark(const QString& note)
{
    if (!m_station.isRecording()) return m_hooks.tell(tr("Markers go into a recording: start one first (Ctrl+R)."));
    add(m_station.device()->sessionTime_s(), note);
}

void LiveMarkers::markWithNote()
{
    if (!m_station.isRecording()) return mark();  // says why not
    const double time_s = m_station.device()->sessionTime_s();
    const std::int64_t session = m_station.pipeline().sessionId();
    askMarkerNote(m_window, time_s, [this, time_s, session, store = m_hooks.store()](const QString& note) {
        if (m_station.isRecording() && m_station.pipeline().sessionId() == session) return add(time_s, note);
        core::storage::Annotation annotation{0, time_s, m_hooks.author(), note.toStdString(), "", ""};
        runOnStore(
            *store, this,
            [session, annotation](core::storage::SessionSource& s) { s.addAnnotation(session, annotation); },
            [this, session] { m_hooks.tell(tr("Note stored in session %1").arg(session)); },
            [this, note](const QString& error) {
                reportProblem(m_window, {tr("Note not stored"), tr("The marker's note could not be stored."), error,
                                         tr("Your note: %1").arg(note)});
            });
    });
}

// In the window's device's recording (a session of several: its part).
void LiveMarkers::add(double time_s, const QString& note)
{
    m_station.device()->addMarker(time_s, note.toStdString());
    m_traces.addMarker(time_s, note);
    m_hooks.tell(tr("Marker at %1 s").arg(fixedText(time_s, 2)));
}

}  // namespace tactiscope::ui
