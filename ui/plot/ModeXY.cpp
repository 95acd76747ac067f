// ModeXY: the XY plot of the mode shown, as its ui entry draws it.
#include "ui/plot/ModeXY.h"

#include "ui/modes/ModeUi.h"
#include "ui/plot/XYPlotWidget.h"

#include <QObject>

namespace tactiscope::ui {

QString showModeXY(XYPlotWidget& plot, const devices::session::LiveSession* session, std::optional<core::Mode> mode)
{
    const auto xy = mode ? modeUi(*mode).liveXY : nullptr;
    if (session && xy) return xy(plot, *session);
    plot.clearSource();
    return QObject::tr("XY plot (the mode shown has none)");
}

}  // namespace tactiscope::ui
