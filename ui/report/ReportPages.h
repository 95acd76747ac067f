// A report's pages: the document laid out on the paper at 96 dpi with 2 cm
// margins on every page, a heading never left at the foot of a page
// without the table or text it heads, then drawn page by page with its
// number at the foot.
// QTextDocument::print() does the pagination by itself and stranded
// "Defect sites (1)" at the bottom of page 1 with its table on page 2.
#pragma once

#include <QSizeF>

class QPagedPaintDevice;
class QTextDocument;

namespace tactiscope::ui {

// A4 in the document's 96-dpi pixels.
QSizeF a4Paper_px();

// Paginates `document` on paper of `paper_px` with 2 cm margins (each
// page's content stays out of its margins, so nothing of a neighbouring
// page is drawn there), moving each heading that would end a page onto
// the next one with what follows it.
void layOutPages(QTextDocument& document, const QSizeF& paper_px);

// The page (from 0) on which the block at `position` of a paginated
// document begins.
int pageAt(const QTextDocument& document, int position);

// Lays `document` out for `device` (its paper, 2 cm margins) and draws it
// there page by page, "page N of M" at each foot. Returns the page count.
int printPages(QTextDocument& document, QPagedPaintDevice& device);

}  // namespace tactiscope::ui
