// The XY plot each mode calls for: F_H against F_L in palpation (its slope
// is Q), force against tip deflection for the capacitive beam (its slope is
// k_s); panel scan has none.
#pragma once

#include "core/Vocabulary.h"

#include <QString>

#include <optional>

namespace tactiscope::devices::session {
class LiveSession;
}

namespace tactiscope::ui {

class XYPlotWidget;

// Shows `mode`'s XY plot of the session's processor on `plot` (cleared when
// there is none) and returns the plot's title.
QString showModeXY(XYPlotWidget& plot, const devices::session::LiveSession* session, std::optional<core::Mode> mode);

}  // namespace tactiscope::ui
