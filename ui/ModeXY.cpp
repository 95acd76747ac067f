// ModeXY: which outputs of which processor, in which display units.
#include "ui/ModeXY.h"

#include "core/capacitive/LiveCapacitive.h"
#include "core/compliance/LivePalpation.h"
#include "devices/session/LiveSession.h"
#include "ui/DisplayUnits.h"
#include "ui/XYPlotWidget.h"

#include <QObject>

namespace tactiscope::ui {

QString showModeXY(XYPlotWidget& plot, const devices::session::LiveSession* session, std::optional<core::Mode> mode)
{
    const double rate_hz = session ? session->source().nominalSampleRate_hz() : 0.0;
    if (session && mode == core::Mode::Palpation && session->palpation()) {
        const DisplayUnit high{1e3, QObject::tr("mN"), QObject::tr("F stiff")};
        const DisplayUnit low{1e3, QObject::tr("mN"), QObject::tr("F soft")};
        plot.setSource(session->palpation()->output(), 1, 0, low, high, rate_hz, QStringLiteral("Q"));
        return QObject::tr("XY plot: F stiff against F soft (slope Q)");
    }
    // A capacitive beam's force and deflection both come from its one
    // capacitance through the model: plotted against each other they make
    // the model's straight line, not a measurement. Not offered.
    plot.clearSource();
    return QObject::tr("XY plot (palpation: F stiff against F soft)");
}

}  // namespace tactiscope::ui
