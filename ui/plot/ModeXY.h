// The XY plot a mode calls for, from its ui entry (palpation: F stiff
// against F soft, whose slope is Q); the other modes have none.
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
