// PalpationFigures: the grid map as a coloured table, the scale drawn off screen.
#include "ui/modes/palpation/PalpationFigures.h"

#include "ui/common/NumberText.h"
#include "ui/modes/palpation/StiffnessScale.h"

#include <QLocale>
#include <QPainter>

#include <algorithm>
#include <map>

namespace tactiscope::ui {

QStringList pressCells(const core::report::PressRow& press)
{
    const QLocale locale;
    const auto [k, se] = valueAndErrorTexts(press.stiffness_n_per_m, press.standardError_n_per_m.value_or(0.0));
    const QString depth = press.depthMin_m && press.depthMax_m
                              ? QStringLiteral("%1 – %2").arg(fixedText(*press.depthMin_m * 1e3, 2),
                                                              fixedText(*press.depthMax_m * 1e3, 2))
                              : QStringLiteral("—");
    return {fixedText(press.start_s, 2), QString::fromStdString(press.site),
            press.standardError_n_per_m ? k + QStringLiteral(" ± ") + se : k, depth};
}

std::vector<QStringList> siteRows(const std::vector<core::report::SiteSummary>& sites)
{
    std::vector<double> deviations;
    for (const auto& site : sites)
        if (site.standardDeviation_n_per_m) deviations.push_back(*site.standardDeviation_n_per_m);
    const int decimals = sharedDecimals(deviations, 1);
    std::vector<QStringList> rows;
    for (const auto& site : sites)
        rows.push_back({QString::fromStdString(site.site), QLocale().toString(static_cast<qulonglong>(site.presses)),
                        fixedText(site.mean_n_per_m, decimals),
                        site.standardDeviation_n_per_m ? fixedText(*site.standardDeviation_n_per_m, decimals)
                                                       : QStringLiteral("—"),
                        rangeText(site.min_n_per_m, site.max_n_per_m, decimals)});
    return rows;
}

QString siteGridHtml(const std::vector<core::report::SiteSummary>& sites)
{
    std::map<std::pair<int, int>, const core::report::SiteSummary*> cells;
    int rows = 0, columns = 0;
    for (const auto& site : sites) {
        const auto cell = core::report::gridCellOf(site.site);
        if (!cell) continue;
        cells[{cell->row, cell->column}] = &site;
        rows = std::max(rows, cell->row + 1);
        columns = std::max(columns, cell->column + 1);
    }
    if (cells.empty()) return {};
    QString html = QStringLiteral("<table cellspacing=2 cellpadding=4><tr><td></td>");
    for (int c = 0; c < columns; ++c) html += QStringLiteral("<th align=center>%1</th>").arg(c + 1);
    html += QStringLiteral("</tr>");
    const QLocale locale;
    for (int r = 0; r < rows; ++r) {
        html += QStringLiteral("<tr><th>%1</th>").arg(QChar(u'A' + r));
        for (int c = 0; c < columns; ++c) {
            const auto found = cells.find({r, c});
            if (found == cells.end()) {
                html += QStringLiteral("<td align=center bgcolor=#f2f2f2 style='color:#999'>—</td>");
                continue;
            }
            const auto& site = *found->second;
            const QColor fill = stiffnessColour(site.mean_n_per_m);
            const QString ink = fill.lightnessF() > 0.55f ? QStringLiteral("#000000") : QStringLiteral("#ffffff");
            html += QStringLiteral("<td align=center bgcolor=%1 style='color:%2'>%3<br><small>n = %4</small></td>")
                        .arg(fill.name(), ink, fixedText(site.mean_n_per_m, 0))
                        .arg(site.presses);
        }
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

void markSites(StiffnessScale& scale, const std::vector<core::report::SiteSummary>& sites)
{
    std::vector<StiffnessScale::Mark> marks;
    for (const auto& site : sites) marks.push_back({QString::fromStdString(site.site), site.mean_n_per_m});
    scale.setMarks(std::move(marks));
}

QImage renderTissueScale(const std::vector<core::report::SiteSummary>& sites, QSize size, double scale)
{
    StiffnessScale widget;
    widget.setTissues(builtInTissues());
    markSites(widget, sites);
    widget.resize(size);
    QImage image(size * scale, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(scale);
    image.fill(Qt::white);
    QPainter painter(&image);
    widget.render(&painter, QPoint(), QRegion(), QWidget::DrawChildren);
    return image;
}

}  // namespace tactiscope::ui
