// SignalQualityHtml: the section's table and lines.
#include "ui/report/SignalQualityHtml.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/report/ReportHtml.h"
#include "ui/signal/HealthText.h"

#include <QObject>

namespace tactiscope::ui {
namespace {

using namespace reporthtml;

QStringList channelRow(const core::report::ChannelQuality& q)
{
    return QStringList{text(q.channel.name)} + healthCells(q);
}

}  // namespace

QString signalQualitySection(const core::report::SignalQuality& quality)
{
    QString html = QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Signal quality"));
    std::vector<QStringList> rows;
    for (const auto& q : quality.channels) rows.push_back(channelRow(q));
    // The filtered and math channels after the stored ones, as they were live.
    for (const auto& q : quality.computed) rows.push_back(channelRow(q));
    html += table(QStringList{QObject::tr("Channel")} + healthHeaders(), rows);
    if (!quality.computedProblem.empty()) html += QStringLiteral("<p>%1</p>").arg(text(quality.computedProblem));
    if (quality.channelsLeftOut > 0)
        html += QStringLiteral("<p>%1</p>")
                    .arg(QObject::tr("… and %n more channel(s): `tactiscope-cli health --db … --session …` reads "
                                     "every one.",
                                     nullptr, static_cast<int>(quality.channelsLeftOut)));
    html += QStringLiteral("<p><small>%1</small></p>")
                .arg(QObject::tr("Over the range reported. Hum: the mains line's amplitude (flat-top); noise floor: "
                                 "the median amplitude spectral density above 1 Hz; drift: a line through 100 "
                                 "interval means, its standard uncertainty (k = 1). Filtered and math channels "
                                 "are computed again from the stored samples, as they were live."));
    html += QStringLiteral("<table class=header>");
    html += row(QObject::tr("Filters and math channels"),
                text(quality.setup) + (quality.setup == "none" ? QString()
                                                               : QObject::tr(" (the samples are stored as they "
                                                                             "came; the filters are a setting)")));
    for (const auto& q : quality.channels) {
        if (!q.creepJudged) continue;
        html += row(QObject::tr("Creep after a load step (%1)").arg(text(q.channel.name)), healthCreepText(q.creep));
    }
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
