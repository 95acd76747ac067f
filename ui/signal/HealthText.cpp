// HealthText: each figure with its unit, or why there is none yet.
#include "ui/signal/HealthText.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include <QObject>

#include <cmath>

namespace tactiscope::ui {

QStringList healthHeaders()
{
    return {QObject::tr("Mains hum"), QObject::tr("Noise floor"), QObject::tr("Drift per hour (± u)"),
            QObject::tr("Clipped samples")};
}

QStringList healthCells(const core::report::ChannelQuality& q)
{
    const DisplayUnit unit = displayUnitFor(q.channel);
    const auto& h = q.health;
    const QString hum = h.hum ? QObject::tr("%1 at %2 Hz")
                                    .arg(withUnit(significantText(h.hum->amplitude * unit.scale, 3), unit.symbol))
                                    .arg(h.hum->mains_hz)
                              : QObject::tr("none");
    const QString floor =
        std::isfinite(h.noiseFloor_per_sqrt_hz)
            ? withUnit(significantText(h.noiseFloor_per_sqrt_hz * unit.scale, 3),
                       (unit.symbol.isEmpty() ? QStringLiteral("1") : unit.symbol) + QStringLiteral("/√Hz"))
            : QObject::tr("no gap-free stretch long enough");
    QString drift = h.span_s < core::dsp::kShortestDrift_s
                        ? QObject::tr("from %1 s on").arg(core::dsp::kShortestDrift_s)
                        : QObject::tr("too much lost");
    if (!q.drifts)
        drift = QObject::tr("— (a position)");
    else if (h.drift)
        drift = withUnit(valueWithErrorText(h.drift->rate_per_s * 3600.0 * unit.scale,
                                            h.drift->standardUncertainty_per_s * 3600.0 * unit.scale),
                         unit.symbol + QStringLiteral("/h"));
    const QString clipped = q.drifts ? QString::number(h.clipped) : QStringLiteral("—");
    return {hum, floor, drift, clipped};
}

// "1.10 ± 0.08 % of the step, time constant 4.1 ± 0.5 s (29 steps; …)".
QString healthCreepText(const std::optional<core::dsp::StepCreep>& creep)
{
    if (!creep)
        return QObject::tr("none told from the noise (it needs load steps standing out of the noise, each held several "
                           "of its time constants)");
    const QString share =
        creep->fractionU ? valueWithErrorText(creep->fraction * 100.0, *creep->fractionU * 100.0) + " %"
                         : QObject::tr("%1 % (a ± needs three steps)").arg(significantText(creep->fraction * 100.0, 2));
    const QString steps = creep->steps == 1 ? QObject::tr("one step") : QObject::tr("%1 steps").arg(creep->steps);
    return QObject::tr("%1 of the step, time constant %2 s (%3 fitted; the beam's own swing has a time constant "
                       "of %4 s)")
        .arg(share, valueWithErrorText(creep->timeConstant_s, creep->timeConstantU_s), steps,
             significantText(creep->settleTime_s, 2));
}

}  // namespace tactiscope::ui
