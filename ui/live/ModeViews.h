// The mode's view under the live traces, one at a time: each mode's live
// view (ui/modes/ModeUi.h) bound to the live session with the probe's name
// and the calibrations it reads through, and fed from the session on each
// status poll. A mode without a view (general), or whose processor is not
// running, shows no view at all. The views follow the live station's
// window device (watch()). A view wider than the window allows scrolls
// sideways, so the window fits a laptop whatever mode runs.
#pragma once

#include "core/Vocabulary.h"

#include <QScrollArea>

class QStackedWidget;

#include <map>
#include <optional>
#include <vector>

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class LivePlotWidget;
class LiveModeView;
class LiveStation;

class ModeViews : public QScrollArea {
    Q_OBJECT

public:
    // Makes the view of every mode that has one.
    explicit ModeViews(QWidget* parent = nullptr);

    // Binds the views to `station`'s device as it comes and goes, feeds
    // them each poll and at a recording's end (the lists then hold what was
    // stored), and lets them mark their events on `traces`.
    void watch(LiveStation& station, LivePlotWidget* traces);

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
    // The view shown; null when none is.
    LiveModeView* shown() const;
    // Sideways it scrolls; upwards it keeps its view's whole height.
    QSize minimumSizeHint() const override;

private:
    QStackedWidget* m_stack;
    std::map<core::Mode, LiveModeView*> m_views;
};

}  // namespace tactiscope::ui
