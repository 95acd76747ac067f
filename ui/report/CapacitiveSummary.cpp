// CapacitiveSummary: the basis as rows of a header-style table.
#include "ui/report/CapacitiveSummary.h"

#include "ui/report/ReportHtml.h"

#include <QObject>

#include <algorithm>

namespace tactiscope::ui {

using namespace reporthtml;

QString capacitiveBasisHtml(const core::report::CapacitiveBasis& c)
{
    QString html = QStringLiteral("<table class=header cellspacing=0 cellpadding=2>");
    if (!c.baselines_f.empty()) {
        const auto [low, high] = std::ranges::minmax(c.baselines_f);
        QString baselines = QObject::tr("%1 pF at the start").arg(number(c.baselines_f.front() * 1e12, 4));
        if (c.baselines_f.size() > 1)
            baselines += (c.baselines_f.size() == 2
                              ? QObject::tr("; 1 later tare or drift step")
                              : QObject::tr("; %1 later tares or drift steps").arg(c.baselines_f.size() - 1)) +
                         QObject::tr(", %1 – %2 pF").arg(number(low * 1e12, 4), number(high * 1e12, 4));
        html += row(QObject::tr("Baseline C<sub>0</sub>"), baselines);
    }
    html +=
        row(QObject::tr("Sensitivity used"), QObject::tr("%1 pF/mN (force), %2 pF/mm (deflection)")
                                                 .arg(number(c.perNewton_f * 1e9, 4), number(c.perMetre_f * 1e9, 4)));
    if (!c.calibration) {
        html += row(QObject::tr("Calibration"),
                    QObject::tr("none recorded with the session: the beam model of the profile"));
        return html + QStringLiteral("</table>");
    }
    const auto& record = *c.calibration;
    const auto value = [&record](const char* name, int decimals, const QString& unit) {
        const auto v = record.value(name);
        return v ? number(*v, decimals) + unit : QStringLiteral("—");
    };
    html += row(QObject::tr("Calibrated"),
                QObject::tr("%1 by %2").arg(text(record.timestampUtc), orDash(record.operatorName)));
    QString slope = value("sensitivity_pf_per_mn", 4, QString());
    if (record.fit.points > 2) slope += QStringLiteral(" ± ") + number(record.fit.slopeStandardError * 1e9, 4);
    html += row(QObject::tr("Force fit"), record.fit.points > 0
                                              ? QObject::tr("%1 pF/mN, R² = %2, %3 points")
                                                    .arg(slope, number(record.fit.rSquared, 5))
                                                    .arg(record.fit.points)
                                              : QObject::tr("%1 pF/mN (the record keeps no fit)").arg(slope));
    const auto limit = record.value("detection_limit_mn");
    html += row(QObject::tr("Detection limit (3σ)"),
                limit ? QObject::tr("%1 µN (%2 mgf), %3 mm")
                            .arg(number(*limit * 1e3, 2), number(*limit * 1e3 / 9.80665, 2),
                                 value("detection_limit_mm", 4, QString()))
                      : QStringLiteral("—"));
    html += row(QObject::tr("Baseline σ, drift"),
                QObject::tr("%1 pF, %2 pF/s")
                    .arg(value("baseline_sigma_pf", 4, QString()), value("drift_pf_per_s", 5, QString())));
    return html + QStringLiteral("</table>");
}

QString capacitiveReportSection(const core::report::ReportData& data)
{
    if (!data.capacitive) return {};
    return QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Capacitive beam")) + capacitiveBasisHtml(*data.capacitive);
}

}  // namespace tactiscope::ui
