// StabilityIndicator: the watch's state in words and a coloured dot.
#include "ui/calibration/StabilityIndicator.h"

#include "ui/calibration/StabilityWatch.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include <cmath>

namespace tactiscope::ui {
namespace {

QString dot(const char* colour)
{
    return QStringLiteral("<span style='color:%1; font-size:large'>●</span>&nbsp;").arg(QLatin1String(colour));
}

}  // namespace

StabilityIndicator::StabilityIndicator(const StabilityWatch* watch, QWidget* parent)
    : QLabel(parent),
      m_watch(watch)
{
    setTextFormat(Qt::RichText);
    setObjectName(QStringLiteral("stabilityIndicator"));
    connect(watch, &StabilityWatch::updated, this, &StabilityIndicator::refresh);
    refresh();
}

void StabilityIndicator::setUnit(const DisplayUnit& unit)
{
    m_unit = unit;
    refresh();
}

void StabilityIndicator::refresh()
{
    const auto value = [&](double v, int digits = 3) {
        return significantText(v * m_unit.scale, digits) + QChar(0x2009) + m_unit.symbol;
    };
    const auto& settings = m_watch->settings();
    if (!m_watch->receiving()) {
        setText(dot("#9e9e9e") + tr("No signal: is the device connected and streaming?"));
        return;
    }
    const auto& w = m_watch->latest();
    if (m_watch->isAveraging()) {
        // The first stable window still held the swing's tail: the reading
        // is the fresh window after it.
        setText(dot("#2e9e44") +
                tr("Stable; averaging a fresh %1 s window for the reading…").arg(typedText(settings.window_s)));
        return;
    }
    if (!w) {
        setText(dot("#9e9e9e") + tr("Collecting a %1 s window…").arg(typedText(settings.window_s)));
        return;
    }
    if (!w->stable) {
        setText(dot("#f5a623") + tr("Settling: drift %1/s (limit %2/s), σ %3 (limit %4)")
                                     .arg(value(w->drift_per_s), value(settings.maxDrift_per_s), value(w->sigma),
                                          value(settings.maxNoise)));
        return;
    }
    setText(dot("#2e9e44") +
            tr("Stable: %1, σ %2, drift %3/s").arg(value(w->mean, 7), value(w->sigma), value(w->drift_per_s)));
}

}  // namespace tactiscope::ui
