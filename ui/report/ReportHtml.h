// The small pieces the report's HTML is written with, shared by the report
// and the review window's panels that show the same tables: escaped text,
// numbers in the user's locale, name–value rows and headed tables.
#pragma once

#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace tactiscope::ui::reporthtml {

// The report's images are drawn at this many pixels per logical pixel: ≈ 290 dpi on paper.
inline constexpr double kReportImageScale = 3.0;

QString text(const std::string& value);    // HTML-escaped
QString orDash(const std::string& value);  // "—" when empty
QString number(double value, int decimals);
QString row(const QString& name, const QString& value);  // a <tr> of a name–value table
// A table with a header row that repeats on each page it runs onto.
QString table(const QStringList& headers, const std::vector<QStringList>& rows);

}  // namespace tactiscope::ui::reporthtml
