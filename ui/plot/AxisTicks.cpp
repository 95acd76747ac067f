// AxisTicks: a tick count with two labels at least, none overlapping.
#include "ui/plot/AxisTicks.h"

#include <QLocale>
#include <qcustomplot.h>

#include <algorithm>

namespace tactiscope::ui {
namespace {

struct TickFit {
    long inside = 0;        // ticks inside the range
    double apart_px = 0.0;  // between neighbours
};

TickFit tryCount(QCPAxis& axis, int count, int height_px)
{
    QCPAxisTicker& ticker = *axis.ticker();
    ticker.setTickCount(count);
    QVector<double> ticks;
    ticker.generate(axis.range(), QLocale(), QLatin1Char('g'), 6, ticks, nullptr, nullptr);
    TickFit fit;
    fit.inside = std::count_if(ticks.begin(), ticks.end(), [&](double t) { return axis.range().contains(t); });
    fit.apart_px = ticks.size() > 1 ? (ticks[1] - ticks[0]) / axis.range().size() * height_px : 0.0;
    return fit;
}

}  // namespace

bool fitTickCount(QCPAxis& axis, int height_px, double line_px, int most)
{
    QCPAxisTicker& ticker = *axis.ticker();
    if (dynamic_cast<QCPAxisTickerText*>(&ticker) || !(axis.range().size() > 0.0)) return false;
    const int was = ticker.tickCount();
    // The most ticks up to `most` that fit; else more steps, as long as
    // their labels still fit, until two stand inside; else one.
    constexpr int kLimit = 10;
    int chosen = 1;
    bool found = false;
    for (int count = std::max(1, most); count >= 1 && !found; --count) {
        const TickFit fit = tryCount(axis, count, height_px);
        if ((found = fit.inside >= 2 && fit.apart_px >= line_px)) chosen = count;
    }
    for (int count = std::max(1, most) + 1; count <= kLimit && !found; ++count) {
        const TickFit fit = tryCount(axis, count, height_px);
        if (fit.apart_px < line_px) break;
        if ((found = fit.inside >= 2)) chosen = count;
    }
    ticker.setTickCount(chosen);
    return chosen != was;
}

}  // namespace tactiscope::ui
