// AxisTicks: a tick count with two labels at least, none overlapping.
#include "ui/plot/AxisTicks.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

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

// The fewest decimals that write `step` exactly (to a millionth of it).
int decimalsOf(double step)
{
    constexpr int kMost = 8;
    for (int d = 0; d <= kMost; ++d) {
        const double scaled = step * std::pow(10.0, d);
        if (std::abs(scaled - std::round(scaled)) <= 1e-6 * scaled) return d;
    }
    return kMost + 1;
}

}  // namespace

QVector<QString> EvenDecimalsTicker::createLabelVector(const QVector<double>& ticks, const QLocale& locale,
                                                       QChar formatChar, int precision)
{
    if (ticks.size() < 2) return QCPAxisTicker::createLabelVector(ticks, locale, formatChar, precision);
    const double step = std::abs(ticks[1] - ticks[0]);
    const double largest = std::max(std::abs(ticks.front()), std::abs(ticks.back()));
    const int decimals = step > 0.0 ? decimalsOf(step) : 9;
    if (decimals > 8 || largest >= 1e6) return QCPAxisTicker::createLabelVector(ticks, locale, formatChar, precision);
    QVector<QString> labels;
    labels.reserve(ticks.size());
    for (const double tick : ticks)  // a zero that rounding left at -1e-19 is no "-0.0000"
        labels.push_back(locale.toString(std::abs(tick) < 1e-6 * step ? 0.0 : tick, 'f', decimals));
    return labels;
}

void useEvenDecimals(QCPAxis& axis)
{
    QSharedPointer<EvenDecimalsTicker> ticker(new EvenDecimalsTicker);
    ticker->setTickCount(axis.ticker()->tickCount());
    axis.setTicker(ticker);
}

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
    // No two labels fit apart: one inside at least, never a bare axis (a
    // 50 px Q lane over 2.60…2.98 had none: its one step's ticks 2.5 and 3).
    for (int count = 1; count <= kLimit && !found; ++count) {
        const TickFit fit = tryCount(axis, count, height_px);
        if ((found = fit.inside == 1 || (fit.inside >= 2 && fit.apart_px >= line_px))) chosen = count;
    }
    ticker.setTickCount(chosen);
    return chosen != was;
}

}  // namespace tactiscope::ui
