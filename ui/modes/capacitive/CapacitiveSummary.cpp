// CapacitiveSummary: the basis as rows of a header-style table.
#include "ui/modes/capacitive/CapacitiveSummary.h"

#include "ui/calibration/CalibrationText.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"
#include "ui/report/ReportHtml.h"

#include <QObject>

#include <algorithm>
#include <optional>

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
    // The sensitivity in use to the decimals its calibration's uncertainty
    // gives, as the calibration row below writes it.
    const auto slopeError = [&c]() -> std::optional<double> {
        if (!c.calibration) return std::nullopt;
        if (const auto e = c.calibration->value("sensitivity_standard_error_pf_per_mn")) return e;
        if (c.calibration->fit.points > 2) return c.calibration->fit.slopeStandardError * 1e9;
        return std::nullopt;
    }();
    const int slopeDecimals = slopeError ? decimalsFor(*slopeError) : 4;
    html += row(QObject::tr("Sensitivity used"),
                QObject::tr("%1 pF/mN (force), %2 pF/mm (deflection)")
                    .arg(number(c.perNewton_f * 1e9, slopeDecimals), number(c.perMetre_f * 1e9, slopeDecimals)));
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
                QObject::tr("%1 by %2").arg(fileDateTime(record.timestampUtc), orDash(record.operatorName)));
    const auto sensitivity = record.value("sensitivity_pf_per_mn");
    const QString slope = !sensitivity ? QStringLiteral("—")
                          : slopeError ? valueWithErrorText(*sensitivity, *slopeError)
                                       : number(*sensitivity, slopeDecimals);
    html += row(QObject::tr("Force fit"), record.fit.points > 0
                                              ? QObject::tr("%1 pF/mN, R² = %2, %3 points")
                                                    .arg(slope, number(record.fit.rSquared, 5))
                                                    .arg(record.fit.points)
                                              : QObject::tr("%1 pF/mN (the record keeps no fit)").arg(slope));
    const auto limit = record.value("detection_limit_mn");
    html += row(QObject::tr("Detection limit (3σ)"),
                !limit ? QStringLiteral("—")
                : record.value("detection_limit_mm")
                    ? QObject::tr("%1, a tip displacement of %2")
                          .arg(detectionLimitText(*limit * 1e-3),
                               siText(*record.value("detection_limit_mm") * 1e-3, QStringLiteral("m"), 3))
                    : detectionLimitText(*limit * 1e-3));
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
