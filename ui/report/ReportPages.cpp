// ReportPages: pagination that keeps headings with their content, and the printing.
#include "ui/report/ReportPages.h"

#include <QAbstractTextDocumentLayout>
#include <QObject>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextTable>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tactiscope::ui {
namespace {

constexpr double kPx_per_mm = 96.0 / 25.4;
constexpr double kMargin_mm = 20.0;

// A table's first body row: its header rows repeat on every page, so they
// are no content.
int firstBodyRow(const QTextTable& table)
{
    return table.cellAt(std::min(table.format().headerRowCount(), table.rows() - 1), 0).firstPosition();
}

// A table this short reads as one piece (a basis's rows, a legend): it is
// not cut across pages.
constexpr int kShortTableRows = 15;

// The document positions a heading (the root-frame item `it`) must share a
// page with: the first body row of its table, when one follows after at
// most a line or two of introduction ("Defect sites (3)", "From the events
// recorded live.", then the sites: the heading and its line alone at a
// page's foot say nothing), and a short table's last row too; else those
// lines of its section ("None found." with them) or another frame's start.
std::vector<int> contentAfter(QTextFrame::iterator it)
{
    constexpr int kIntroductionBlocks = 2;
    std::vector<int> blocks;
    for (++it; !it.atEnd(); ++it) {
        if (QTextFrame* frame = it.currentFrame()) {
            if (auto* table = qobject_cast<QTextTable*>(frame)) {
                blocks = {firstBodyRow(*table)};
                if (table->rows() <= kShortTableRows)
                    blocks.push_back(table->cellAt(table->rows() - 1, 0).firstPosition());
                return blocks;
            }
            if (blocks.empty()) blocks.push_back(frame->firstPosition());
            return blocks;
        }
        const QTextBlock block = it.currentBlock();
        if (!block.isValid() || block.text().trimmed().isEmpty()) continue;
        if (block.blockFormat().headingLevel() != 0) break;  // the next section: no table of this one
        blocks.push_back(block.position());
        if (static_cast<int>(blocks.size()) >= kIntroductionBlocks) break;
    }
    return blocks;
}

}  // namespace

QSizeF a4Paper_px()
{
    return {210.0 * kPx_per_mm, 297.0 * kPx_per_mm};
}

int pageAt(const QTextDocument& document, int position)
{
    const QTextBlock block = document.findBlock(position);
    const QRectF box = document.documentLayout()->blockBoundingRect(block);
    return static_cast<int>(std::floor(box.top() / document.pageSize().height()));
}

void layOutPages(QTextDocument& document, const QSizeF& paper_px)
{
    QTextFrameFormat margins = document.rootFrame()->frameFormat();
    margins.setMargin(kMargin_mm * kPx_per_mm);
    document.rootFrame()->setFrameFormat(margins);
    document.setPageSize(paper_px);
    // Each move pushes what follows down: look again from the top until
    // no heading is stranded (a heading moves once, so this ends).
    for (bool moved = true; moved;) {
        moved = false;
        for (auto it = document.rootFrame()->begin(); !it.atEnd() && !moved; ++it) {
            QTextBlock heading = it.currentBlock();
            if (!heading.isValid() || heading.blockFormat().headingLevel() == 0) continue;
            if (heading.blockFormat().pageBreakPolicy() & QTextFormat::PageBreak_AlwaysBefore) continue;
            const int page = pageAt(document, heading.position());
            const auto content = contentAfter(it);
            if (std::ranges::all_of(content, [&](int position) { return pageAt(document, position) == page; }))
                continue;
            QTextCursor cursor(heading);
            QTextBlockFormat format = heading.blockFormat();
            format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
            cursor.setBlockFormat(format);
            moved = true;
        }
    }
}

int printPages(QTextDocument& document, QPagedPaintDevice& device)
{
    device.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
    const QSizeF paper_mm = device.pageLayout().fullRect(QPageLayout::Millimeter).size();
    const QSizeF page(paper_mm.width() * kPx_per_mm, paper_mm.height() * kPx_per_mm);
    layOutPages(document, page);
    const int pages = document.pageCount();
    QPainter painter(&device);
    const double margin = kMargin_mm * kPx_per_mm;
    painter.scale(device.logicalDpiX() / 96.0, device.logicalDpiY() / 96.0);
    QFont footer = document.defaultFont();
    footer.setPixelSize(9);  // in the document's pixels, which the painter scales to the device
    for (int p = 0; p < pages; ++p) {
        if (p > 0) device.newPage();
        painter.save();
        painter.translate(0, -p * page.height());
        document.drawContents(&painter, QRectF(0, p * page.height(), page.width(), page.height()));
        painter.restore();
        painter.setFont(footer);
        painter.setPen(QColor(0x77, 0x77, 0x77));
        painter.drawText(QRectF(margin, page.height() - margin, page.width() - 2 * margin, margin / 2),
                         Qt::AlignRight | Qt::AlignVCenter, QObject::tr("page %1 of %2").arg(p + 1).arg(pages));
    }
    return pages;
}

}  // namespace tactiscope::ui
