// The inspection report of a session as a document: a header (subject,
// operator, date, device, sensor and calibration, the range covered), the
// verdict or the readings' summary, the key plot, and the tables of events,
// readings and notes. One HTML text laid out by Qt's rich-text engine, so
// the same document becomes a paginated PDF (A4, real text that pdftotext
// reads) or goes to a printer.
#pragma once

#include "core/report/ReportData.h"

#include <QString>

#include <memory>

class QTextDocument;

namespace tactiscope::ui {

// The document with its plot image; printPages (ReportPages) lays it out
// on the pages of a printer or PDF writer.
std::unique_ptr<QTextDocument> buildReportDocument(const core::report::ReportData& data);

// Writes the PDF (A4) atomically: a temporary file, every write checked,
// renamed into place; a full disk leaves no file. Returns the page count
// of the PDF written; throws std::runtime_error when it cannot be written.
int writeReportPdf(const core::report::ReportData& data, const QString& path);

}  // namespace tactiscope::ui
