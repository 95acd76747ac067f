// Palpation's part in the ui (seed 001): the presses, stiffness readout
// and grid map live, F stiff against F soft as the live XY plot (its slope
// is Q), the forces, Q and kₒ as review lanes in mN and N/m, the gauge
// factor's wizard, the presses and sites beside the review's list and in
// the report, and the compliance probe's design tool.
#include "ui/modes/ModeUi.h"

#include "devices/session/modes/PalpationUnit.h"

#include "core/compliance/LivePalpation.h"
#include "devices/session/LiveSession.h"
#include "ui/modes/palpation/DesignTool.h"
#include "ui/modes/palpation/GaugeFactorWizard.h"
#include "ui/modes/palpation/PalpationReport.h"
#include "ui/modes/palpation/PalpationView.h"
#include "ui/modes/palpation/PressesPanel.h"
#include "ui/plot/XYPlotWidget.h"
#include "ui/profiles/ProfileLibrary.h"

#include <QObject>

namespace tactiscope::ui {
namespace {

DisplayUnit force(const QString& title)
{
    return {1e3, QStringLiteral("mN"), title};
}

std::optional<DisplayUnit> laneUnit(std::string_view lane)
{
    if (lane == "force_high") return force(QObject::tr("F stiff"));
    if (lane == "force_low") return force(QObject::tr("F soft"));
    if (lane == "Q") return DisplayUnit{1.0, {}, QObject::tr("Q")};
    if (lane == "stiffness") return DisplayUnit{1.0, QStringLiteral("N/m"), QObject::tr("kₒ")};
    return std::nullopt;
}

QString liveXY(XYPlotWidget& plot, const devices::session::LiveSession& session)
{
    const auto* unit = session.unitAs<devices::session::PalpationUnit>();
    if (!unit) {
        plot.clearSource();
        return QObject::tr("XY plot: F stiff against F soft (no palpation output)");
    }
    plot.setSource(unit->palpation()->output(), 1, 0, force(QObject::tr("F soft")), force(QObject::tr("F stiff")),
                   session.source().nominalSampleRate_hz(), QStringLiteral("Q"));
    return QObject::tr("XY plot: F stiff against F soft (slope Q)");
}

}  // namespace

const ModeUi& palpationUi()
{
    static const ModeUi entry{
        .mode = core::Mode::Palpation,
        .liveView = [](QWidget* parent) -> LiveModeView* { return new PalpationView(parent); },
        .laneUnit = laneUnit,
        .calibrateAction = [] { return QObject::tr("Calibrate the &gauge factor…"); },
        .calibrationWizard = [](CalibrationContext context, QWidget* parent) -> CalibrationWizard* {
            return new GaugeFactorWizard(std::move(context), parent);
        },
        .liveXY = liveXY,
        .reviewAccount = [](const ReviewAccountContext& context, QWidget* parent) -> ReviewAccount* {
            return new PressesPanel(context, parent);
        },
        .reportSection = palpationReportSection,
        .toolAction = [] { return QObject::tr("Compliance probe &design…"); },
        .openTool =
            [](QWidget* parent) {
                auto* tool = new DesignTool(ProfileLibrary::defaultDirectory(), parent);
                tool->setAttribute(Qt::WA_DeleteOnClose);
                tool->show();
            },
    };
    return entry;
}

}  // namespace tactiscope::ui
