// FixedColumns: stable table columns.
#include "ui/common/FixedColumns.h"

#include <QHeaderView>
#include <QScrollBar>
#include <QStyle>
#include <QTableView>

#include <algorithm>

namespace tactiscope::ui {

void fitColumns(QTableView& table, const QStringList& widest)
{
    QHeaderView& header = *table.horizontalHeader();
    const auto* model = table.model();
    const int padding = 2 * table.style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, &header) + 6;
    int total = 0;
    for (int column = 0; column < header.count() && column < widest.size(); ++column) {
        const QString title = model ? model->headerData(column, Qt::Horizontal).toString() : QString();
        const int width = std::max(header.fontMetrics().horizontalAdvance(title),
                                   table.fontMetrics().horizontalAdvance(widest[column])) +
                          padding;
        header.setSectionResizeMode(column, QHeaderView::Interactive);
        header.resizeSection(column, width);
        total += width;
    }
    header.setStretchLastSection(true);
    table.setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    table.setMinimumWidth(total + table.verticalScrollBar()->sizeHint().width() + 2 * table.frameWidth() +
                          (table.verticalHeader()->isHidden() ? 0 : table.verticalHeader()->sizeHint().width()));
}

}  // namespace tactiscope::ui
