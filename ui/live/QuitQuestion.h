// Quitting while recording asks first (issue 37): *Keep recording* keeps
// the window and the recording; *Stop recording* ends the session, with
// the verdict step in a mode that has one (the operator's to answer, in
// the open window), then quits once it is answered (issue 52: it used to
// stop and stay).
#pragma once

#include <QObject>

class QMainWindow;

namespace tactiscope::ui {

class LiveStation;
class VerdictDialog;

class QuitQuestion : public QObject {
    Q_OBJECT

public:
    QuitQuestion(LiveStation& station, QMainWindow* window);

    // Whether the window may close now; when not, the question is asked.
    bool mayClose();
    // A recording ended; `asked`: the verdict its stop asked, if any.
    void recordingEnded(VerdictDialog* asked);

private:
    void ask();

    LiveStation& m_station;
    QMainWindow* m_window;
    bool m_quitAfterStop = false;  // Stop recording was chosen: quit once it is done
};

}  // namespace tactiscope::ui
