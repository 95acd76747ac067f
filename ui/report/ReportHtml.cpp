// ReportHtml: the report's HTML building blocks.
#include "ui/report/ReportHtml.h"

#include "ui/common/NumberText.h"

#include <QLocale>

namespace tactiscope::ui::reporthtml {

QString text(const std::string& value)
{
    return QString::fromStdString(value).toHtmlEscaped();
}

QString orDash(const std::string& value)
{
    return value.empty() ? QStringLiteral("—") : text(value);
}

QString number(double value, int decimals)
{
    return fixedText(value, decimals);
}

QString row(const QString& name, const QString& value)
{
    return QStringLiteral("<tr><th align=left>%1</th><td>%2</td></tr>").arg(name, value);
}

QString table(const QStringList& headers, const std::vector<QStringList>& rows)
{
    // A header row (thead) is repeated on each page a long table runs onto.
    QString html = QStringLiteral("<table class=list width=100% cellspacing=0 cellpadding=3><thead><tr>");
    for (const QString& header : headers) html += QStringLiteral("<th align=left>%1</th>").arg(header);
    html += QStringLiteral("</tr></thead>");
    for (const QStringList& cells : rows) {
        html += QStringLiteral("<tr>");
        for (const QString& cell : cells) html += QStringLiteral("<td>%1</td>").arg(cell);
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

}  // namespace tactiscope::ui::reporthtml
