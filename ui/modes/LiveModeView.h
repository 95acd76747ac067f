// A mode's view under the live traces, as the main window sees every one:
// bound to the live session (its processor, probe and calibrations), fed on
// each status poll from the session's one model, with the lanes that follow
// the traces' clock, marking its events on the traces when it has any.
// Each mode's view (PanelScanView, PalpationView,
// CapacitiveView) implements it; ui/modes/ModeUi.h says which view a mode has.
#pragma once

#include <QWidget>

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class LivePlotWidget;

class LiveModeView : public QWidget {
    Q_OBJECT

public:
    using QWidget::QWidget;

    // Shows the session's processor of this view's mode; null (or a session
    // that does not run it) detaches.
    virtual void bind(const devices::session::LiveSession* session) = 0;
    // One status poll: the session's lists and readings as they are now.
    virtual void update(devices::session::LiveSession& session) = 0;
    // The processor's output as lanes under the traces.
    virtual LivePlotWidget* lanes() const = 0;
    // The device's traces above it, for a view that marks its events there
    // (the panel's defects where they happened); none by default.
    virtual void setTraces(LivePlotWidget* traces) { static_cast<void>(traces); }

signals:
    void profilesRequested();  // the probe line's "Change…" link
    void tareRequested();      // the tare button
};

}  // namespace tactiscope::ui
