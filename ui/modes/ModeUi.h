// A mode's part in the user interface, in one entry the rest of the ui asks
// instead of switching on the mode: its live view, the units its derived
// quantities are shown in, its calibration wizard, its live XY plot, its
// account in the review window, its section of the report and a tool of
// its own. Each
// built-in mode has its entry in its own file beside this one
// (panelscan/PanelScanUi.cpp, …); ModeUiRegistry.cpp lists them. A mode without an
// entry (general) has none of these parts: the device's traces, the list of
// records and the report's tables say all there is.
#pragma once

#include "core/Vocabulary.h"
#include "ui/calibration/CalibrationContext.h"
#include "ui/common/DisplayUnits.h"

#include <QString>

#include <optional>
#include <string_view>

class QTextDocument;
class QWidget;

namespace tactiscope::core::report {
struct ReportData;
}
namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class CalibrationWizard;
class LiveModeView;
class ReviewAccount;
struct ReviewAccountContext;
class XYPlotWidget;

struct ModeUi {
    core::Mode mode;
    // Its view under the live traces.
    LiveModeView* (*liveView)(QWidget* parent) = nullptr;
    // How a lane of its derived quantities (core/derived) is shown, by the
    // lane's name; none for a name it does not know.
    std::optional<DisplayUnit> (*laneUnit)(std::string_view lane) = nullptr;
    // Its calibration: the Tools menu's entry and the wizard.
    QString (*calibrateAction)() = nullptr;
    CalibrationWizard* (*calibrationWizard)(CalibrationContext context, QWidget* parent) = nullptr;
    // Shows its XY plot of the session's processor; returns the plot's title.
    QString (*liveXY)(XYPlotWidget& plot, const devices::session::LiveSession& session) = nullptr;
    // Its account beside the review window's list of records.
    ReviewAccount* (*reviewAccount)(const ReviewAccountContext& context, QWidget* parent) = nullptr;
    // Its section of the report (HTML); without one the report lists the
    // session's readings as a table.
    QString (*reportSection)(const core::report::ReportData& data, QTextDocument& document) = nullptr;
    // A tool of its own in the Tools menu (the compliance probe's design):
    // the entry's text and the window it opens, non-modal.
    QString (*toolAction)() = nullptr;
    void (*openTool)(QWidget* parent) = nullptr;
};

// The entry of `mode`; a mode without one gets an entry with no parts.
const ModeUi& modeUi(core::Mode mode);
// Adds or replaces a mode's entry (a test's, a plugin's); unregister takes it out.
void registerModeUi(const ModeUi& entry);
void unregisterModeUi(core::Mode mode);

// The built-in modes' entries, each in its own file.
const ModeUi& panelScanUi();
const ModeUi& palpationUi();
const ModeUi& capacitiveUi();

}  // namespace tactiscope::ui
