// The panel scan's part in the ui (seed 000): the detector's lanes and
// defect list live, its decision and best R as review lanes, and the
// re-analysis beside the review's list. It has no calibration and no XY plot.
#include "ui/modes/ModeUi.h"

#include "ui/modes/panelscan/PanelScanView.h"
#include "ui/review/ReanalysisPanel.h"

#include <QObject>

namespace tactiscope::ui {
namespace {

std::optional<DisplayUnit> laneUnit(std::string_view lane)
{
    if (lane == "best_r") {
        DisplayUnit correlation{1.0, {}, QObject::tr("Best R")};
        correlation.decimals = 3;  // a correlation, within ±1
        return correlation;
    }
    if (lane == "decision")
        return DisplayUnit{1.0,
                           {},
                           QObject::tr("Decision"),
                           {{-1.0, QObject::tr("B→A")}, {0.0, QObject::tr("none")}, {1.0, QObject::tr("A→B")}}};
    return std::nullopt;
}

}  // namespace

const ModeUi& panelScanUi()
{
    static const ModeUi entry{
        .mode = core::Mode::PanelScan,
        .liveView = [](QWidget* parent) -> LiveModeView* { return new PanelScanView(parent); },
        .laneUnit = laneUnit,
        .reviewAccount = [](const ReviewAccountContext& context, QWidget* parent) -> ReviewAccount* {
            return new ReanalysisPanel(context, parent);
        },
    };
    return entry;
}

}  // namespace tactiscope::ui
