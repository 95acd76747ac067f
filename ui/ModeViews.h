// The mode's view under the live traces, one at a time: each mode's live
// view (ui/modes/ModeUi.h) bound to the live session with the probe's name
// and the calibrations it reads through, and fed from the session on each
// status poll. A mode without a view (general), or whose processor is not
// running, shows no view at all.
#pragma once

#include "core/Vocabulary.h"

#include <QStackedWidget>

#include <map>
#include <optional>
#include <vector>

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class LivePlotWidget;
class LiveModeView;

class ModeViews : public QStackedWidget {
    Q_OBJECT

public:
    // Makes the view of every mode that has one.
    explicit ModeViews(QWidget* parent = nullptr);

    // Each mode's view; null for a mode without one.
    LiveModeView* view(core::Mode mode) const;
    std::vector<LiveModeView*> views() const;
    std::vector<LivePlotWidget*> lanes() const;

    // Binds the view of `mode` to the session (none: unbinds).
    void bind(const devices::session::LiveSession* session, core::Mode mode);
    void bindAll(const devices::session::LiveSession* session);
    // Shows the view of `mode` when the session runs its unit, else hides
    // the stack; returns the mode shown.
    std::optional<core::Mode> show(const devices::session::LiveSession* session, core::Mode mode);
    // One status poll of every view.
    void update(devices::session::LiveSession& session);

private:
    std::map<core::Mode, LiveModeView*> m_views;
};

}  // namespace tactiscope::ui
