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
        const DisplayUnit high{1e3, QObject::tr("mN"), QObject::tr("F_H")};
        const DisplayUnit low{1e3, QObject::tr("mN"), QObject::tr("F_L")};
        plot.setSource(session->palpation()->output(), 1, 0, low, high, rate_hz);
        return QObject::tr("XY plot: F_H against F_L (slope Q)");
    }
    if (session && mode == core::Mode::Capacitive && session->capacitive()) {
        const DisplayUnit deflection{1e3, QObject::tr("mm"), QObject::tr("Tip deflection")};
        const DisplayUnit force{1e6, QObject::tr("µN"), QObject::tr("Force")};
        plot.setSource(session->capacitive()->output(), 1, 0, deflection, force, rate_hz);
        return QObject::tr("XY plot: force against deflection (slope k_s)");
    }
    plot.clearSource();
    return QObject::tr("XY plot (palpation and capacitive modes)");
}

}  // namespace tactiscope::ui
