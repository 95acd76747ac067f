// PalpationReport: the presses, sites, grid map and scale as report HTML.
#include "ui/modes/palpation/PalpationReport.h"

#include "core/report/PressTable.h"
#include "core/storage/SessionRecords.h"
#include "ui/modes/palpation/PalpationFigures.h"
#include "ui/report/ReportHtml.h"

#include <QObject>
#include <QSize>
#include <QTextDocument>
#include <QUrl>

namespace tactiscope::ui {
namespace {

constexpr int kScaleWidth_px = 300;
constexpr int kScaleHeight_px = 260;

}  // namespace

using namespace reporthtml;

QString palpationReportSection(const core::report::ReportData& data, QTextDocument& document)
{
    const auto presses = core::report::pressRows(data.readings);
    if (presses.empty()) return {};
    std::vector<QStringList> rows;
    const auto escaped = [](QStringList cells) {
        for (QString& cell : cells) cell = cell.toHtmlEscaped();
        return cells;
    };
    for (const auto& p : presses) rows.push_back(escaped(pressCells(p)));
    QString html = QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Presses (%1)").arg(presses.size()));
    if (data.analysis != core::storage::kLiveAnalysis)
        html += QStringLiteral("<p>%1</p>")
                    .arg(QObject::tr("From the saved re-analysis \"%1\" (the recorded readings are in the session).")
                             .arg(text(data.analysis)));
    html += table({QObject::tr("Time (s)"), QObject::tr("Site"), QObject::tr("k<sub>o</sub> ± u (N/m)"),
                   QObject::tr("Depth (mm)")},
                  rows);
    html += QStringLiteral("<p>%1</p>")
                .arg(QObject::tr("u: standard uncertainty from the force noise and the zero's uncertainty; the "
                                 "beam model's systematic terms (E, t³, L³) are not in it."));
    const auto sites = core::report::siteSummaries(presses);
    if (!sites.empty()) {
        std::vector<QStringList> sitesTable;
        for (const auto& cells : siteRows(sites)) sitesTable.push_back(escaped(cells));
        html += QStringLiteral("<h2>%1</h2>").arg(QObject::tr("By site"));
        html += table({QObject::tr("Site"), QObject::tr("n"), QObject::tr("Mean (N/m)"), QObject::tr("SD (N/m)"),
                       QObject::tr("Range (N/m)")},
                      sitesTable);
    }
    const QUrl scaleUrl(QStringLiteral("tactiscope://tissue-scale.png"));
    document.addResource(QTextDocument::ImageResource, scaleUrl,
                         renderTissueScale(core::report::scaleMarks(presses, QObject::tr("all").toStdString()),
                                           QSize(kScaleWidth_px, kScaleHeight_px), kReportImageScale));
    const QString grid = siteGridHtml(sites);
    html += QStringLiteral("<h2>%1</h2>")
                .arg(grid.isEmpty() ? QObject::tr("Tissue scale") : QObject::tr("Site map and tissue scale"));
    html += QStringLiteral("<table cellspacing=0 cellpadding=6><tr><td valign=top>%1</td>"
                           "<td valign=top><img src='%2' width=%3 height=%4></td></tr></table>")
                .arg(grid)
                .arg(scaleUrl.toString())
                .arg(kScaleWidth_px)
                .arg(kScaleHeight_px);
    return html + QStringLiteral("<p><small>%1</small></p>")
                      .arg(QObject::tr("Each cell and red arrow: the mean object stiffness of a site's presses, "
                                       "against the reference tissues of seed 001."));
}

}  // namespace tactiscope::ui
