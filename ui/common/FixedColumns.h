// Table columns that keep their widths while rows come and go: each wide
// enough for its header and the widest value it will hold, the vertical
// scroll bar always there, the table never narrower than its columns. A
// live table sized to its contents jumped as rows arrived, and the scroll
// bar's arrival cut "Lag (ms)" to "ag (ms)".
#pragma once

#include <QStringList>

class QTableView;

namespace tactiscope::ui {

// `widest`: per column, a text as wide as any value it will show.
void fitColumns(QTableView& table, const QStringList& widest);

}  // namespace tactiscope::ui
