// SignalQualityHtml: the section's table and lines.
#include "ui/report/SignalQualityHtml.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/report/ReportHtml.h"

#include <QObject>

#include <cmath>

namespace tactiscope::ui {
namespace {

using namespace reporthtml;

QString withUnit(const QString& value, const QString& unit)
{
    return unit.isEmpty() ? value : value + QStringLiteral(" ") + unit;
}

QStringList channelRow(const core::report::ChannelQuality& q)
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
            : QObject::tr("too short");
    QString drift = QObject::tr("too short");
    if (!q.drifts)
        drift = QObject::tr("— (a position)");
    else if (h.drift)
        drift = withUnit(significantText(h.drift->rate_per_s * 3600.0 * unit.scale, 3) + QStringLiteral(" ± ") +
                             significantText(h.drift->standardUncertainty_per_s * 3600.0 * unit.scale, 2),
                         unit.symbol + QStringLiteral("/h"));
    const QString clipped = q.drifts ? QString::number(h.clipped) : QStringLiteral("—");
    return {text(q.channel.name), hum, floor, drift, clipped};
}

}  // namespace

QString signalQualitySection(const core::report::SignalQuality& quality)
{
    QString html = QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Signal quality"));
    std::vector<QStringList> rows;
    for (const auto& q : quality.channels) rows.push_back(channelRow(q));
    html += table({QObject::tr("Channel"), QObject::tr("Mains hum"), QObject::tr("Noise floor"),
                   QObject::tr("Drift per hour (± u)"), QObject::tr("Clipped samples")},
                  rows);
    if (quality.channelsLeftOut > 0)
        html += QStringLiteral("<p>%1</p>")
                    .arg(QObject::tr("… and %n more channel(s): `tactiscope-cli health --db … --session …` reads "
                                     "every one.",
                                     nullptr, static_cast<int>(quality.channelsLeftOut)));
    html += QStringLiteral("<p><small>%1</small></p>")
                .arg(QObject::tr("Over the range reported. Hum: the mains line's amplitude (flat-top); noise floor: "
                                 "the median amplitude spectral density above 1 Hz; drift: a line through 100 "
                                 "interval means, its standard uncertainty (k = 1)."));
    html += QStringLiteral("<table class=header>");
    html += row(QObject::tr("Filters and math channels"),
                text(quality.setup) + (quality.setup == "none" ? QString()
                                                               : QObject::tr(" (the samples are stored as they "
                                                                             "came; the filters are a setting)")));
    if (quality.detection) {
        const auto& d = quality.detection;
        const QString fromFloor = withUnit(significantText(d->fromNoiseFloor_n * 1e6, 3), QStringLiteral("µN"));
        const QString fromCalibration =
            d->fromCalibration_n ? withUnit(significantText(*d->fromCalibration_n * 1e6, 3), QStringLiteral("µN"))
                                 : QObject::tr("no calibration with one");
        html += row(QObject::tr("Detection limit (3σ/S)"),
                    QObject::tr("%1 from this recording's noise floor over the band it samples; %2 from the "
                                "calibration's baseline")
                        .arg(fromFloor, fromCalibration));
        if (d->fromCalibration_n && *d->fromCalibration_n > 2.0 * d->fromNoiseFloor_n)
            html += row(QString(), QObject::tr("The calibration's baseline held more than this noise (creep or "
                                               "drift in its window): its limit is the one to quote."));
    }
    return html + QStringLiteral("</table>");
}

}  // namespace tactiscope::ui
