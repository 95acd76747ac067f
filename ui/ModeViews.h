// The mode's view under the live traces, one at a time: the panel-scan
// defect lanes, the palpation presses and the capacitive readouts, each
// bound to the live session's processor with the probe's name and the
// calibrations it reads through, and fed from the session on each status
// poll. A mode whose processor is not running shows no view at all.
#pragma once

#include "core/Vocabulary.h"

#include <QStackedWidget>

#include <optional>
#include <vector>

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class CapacitiveView;
class LivePlotWidget;
class PalpationView;
class PanelScanView;

class ModeViews : public QStackedWidget {
    Q_OBJECT

public:
    explicit ModeViews(QWidget* parent = nullptr);

    PanelScanView* panelScan() const { return m_panelScan; }
    PalpationView* palpation() const { return m_palpation; }
    CapacitiveView* capacitive() const { return m_capacitive; }
    std::vector<LivePlotWidget*> lanes() const;

    // Binds the view of `mode` to the session's processor (none: unbinds).
    void bind(const devices::session::LiveSession* session, core::Mode mode);
    void bindAll(const devices::session::LiveSession* session);
    // Shows the view of `mode` when its processor runs, else hides the
    // stack; returns the mode shown.
    std::optional<core::Mode> show(const devices::session::LiveSession* session, core::Mode mode);
    // One status poll: the site pressed, the defects, presses and readouts.
    void update(devices::session::LiveSession& session);

private:
    PanelScanView* m_panelScan;
    PalpationView* m_palpation;
    CapacitiveView* m_capacitive;
};

}  // namespace tactiscope::ui
