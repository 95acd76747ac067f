// The capacitive beam's part in the ui (seed 002): C, ΔC, force and
// deflection readouts live, ΔC, ΔC/C₀, force and deflection as review lanes
// in pF, %, µN and mm, the C0-and-sensitivity wizard, and the calibration a
// session is read through beside the review's list and in the report. No
// live XY plot: force and deflection both come from the one capacitance
// through the model, so against each other they draw the model's line, not
// a measurement.
#include "ui/modes/ModeUi.h"

#include "ui/modes/capacitive/CapacitiveBasisBox.h"
#include "ui/modes/capacitive/CapacitiveSummary.h"
#include "ui/modes/capacitive/CapacitiveView.h"
#include "ui/modes/capacitive/CapacitiveWizard.h"

#include <QObject>

namespace tactiscope::ui {
namespace {

std::optional<DisplayUnit> laneUnit(std::string_view lane)
{
    if (lane == "delta_c") return DisplayUnit{1e12, QStringLiteral("pF"), QObject::tr("ΔC")};
    if (lane == "relative_change") return DisplayUnit{1e2, QStringLiteral("%"), QObject::tr("ΔC/C₀")};
    if (lane == "force") return DisplayUnit{1e6, QStringLiteral("µN"), QObject::tr("Force")};
    if (lane == "deflection") return DisplayUnit{1e3, QStringLiteral("mm"), QObject::tr("Deflection")};
    return std::nullopt;
}

}  // namespace

const ModeUi& capacitiveUi()
{
    static const ModeUi entry{
        .mode = core::Mode::Capacitive,
        .liveView = [](QWidget* parent) -> LiveModeView* { return new CapacitiveView(parent); },
        .laneUnit = laneUnit,
        .calibrateAction = [] { return QObject::tr("Calibrate the &capacitive beam (C0, sensitivity)…"); },
        .calibrationWizard = [](CalibrationContext context, QWidget* parent) -> CalibrationWizard* {
            return new CapacitiveWizard(std::move(context), parent);
        },
        .reviewAccount = [](const ReviewAccountContext& context, QWidget* parent) -> ReviewAccount* {
            return new CapacitiveBasisBox(context, parent);
        },
        .reportSection = [](const core::report::ReportData& data,
                            QTextDocument&) { return capacitiveReportSection(data); },
    };
    return entry;
}

}  // namespace tactiscope::ui
