// The report's pages (issue 37): a heading is never the last thing on a
// page with its table on the next. A sweep of reports whose tables grow a
// row at a time walks every heading down through a page's foot; the
// pages are checked from Qt's own layout of each block, as the PDF is
// drawn from it, not from the code that moves the headings.
#include "ui/report/ReportPages.h"
#include "ui/report/ReportDocument.h"

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include <QAbstractTextDocumentLayout>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextTable>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace tactiscope;

namespace {

core::report::ReportData sessionWithNotes(const QTemporaryDir& dir)
{
    core::storage::SessionStore store(dir.filePath(QStringLiteral("p.tactiscope")).toStdString());
    core::storage::SessionMetadata metadata;
    metadata.mode = core::Mode::Capacitive;
    const std::vector<core::ChannelDescriptor> channels{{"C", "F", core::ChannelKind::Capacitance}};
    const auto id = store.beginSession(metadata, channels, 10.0);
    core::SampleBlock block(1, 100, 0.0, 0.1, 0);
    for (std::size_t i = 0; i < 100; ++i) block.channel(0)[i] = 51.44e-12 + 1e-15 * static_cast<double>(i);
    store.appendBlocks(id, std::span(&block, 1));
    store.endSession(id, core::SessionStatus::Complete);
    return core::report::gatherReport(store, id);
}

// A panel scan with three defect crossings: its report has the heading
// "Defect sites", a line saying where they come from, then the table.
core::report::ReportData panelWithDefects(const QTemporaryDir& dir)
{
    core::storage::SessionStore store(dir.filePath(QStringLiteral("d.tactiscope")).toStdString());
    core::storage::SessionMetadata metadata;
    metadata.mode = core::Mode::PanelScan;
    const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain},
                                                        {"b", "", core::ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, 100.0);
    core::SampleBlock block(2, 500, 0.0, 0.01, 0);
    store.appendBlocks(id, std::span(&block, 1));
    using core::EventKind;
    store.addEvents(
        id, std::vector<core::storage::SessionEvent>{{0, "live", EventKind::Defect, 1.0, 1.1, 1, 0.95, 0.05, 0.3, ""},
                                                     {0, "live", EventKind::Defect, 2.0, 2.1, -1, 0.93, 0.05, 0.3, ""},
                                                     {0, "live", EventKind::Defect, 4.0, 4.1, 1, 0.9, 0.05, 0.3, ""}});
    store.endSession(id, core::SessionStatus::Complete);
    return core::report::gatherReport(store, id);
}

int pageOf(const QTextDocument& document, const QTextBlock& block)
{
    return static_cast<int>(
        std::floor(document.documentLayout()->blockBoundingRect(block).top() / document.pageSize().height()));
}

// Headings cut from what they head, as "heading: page a, its table page
// b": the first row of their table (after the repeated header), or of a
// table of at most 15 rows its last too (one piece: a basis, a legend);
// with no table, their section's next two lines ("From the events
// recorded live.", "None found."). A table counts as the heading's when at
// most one line of text stands between them.
std::vector<std::string> strandedHeadings(const QTextDocument& document)
{
    std::vector<std::string> stranded;
    for (auto it = document.rootFrame()->begin(); !it.atEnd(); ++it) {
        const QTextBlock heading = it.currentBlock();
        if (!heading.isValid() || heading.blockFormat().headingLevel() != 2) continue;
        std::vector<QTextBlock> content;
        auto next = it;
        for (++next; !next.atEnd() && content.size() < 2; ++next) {
            if (auto* table = qobject_cast<QTextTable*>(next.currentFrame())) {
                if (content.size() > 1) break;
                content = {document.findBlock(table->cellAt(table->format().headerRowCount(), 0).firstPosition())};
                if (table->rows() <= 15)
                    content.push_back(document.findBlock(table->cellAt(table->rows() - 1, 0).firstPosition()));
                break;
            }
            if (next.currentFrame()) break;
            const QTextBlock block = next.currentBlock();
            if (!block.isValid() || block.text().trimmed().isEmpty()) continue;
            if (block.blockFormat().headingLevel() != 0) break;
            content.push_back(block);
        }
        for (const QTextBlock& block : content)
            if (pageOf(document, heading) != pageOf(document, block)) {
                stranded.push_back(heading.text().toStdString() + ": page " +
                                   std::to_string(pageOf(document, heading)) + ", its table page " +
                                   std::to_string(pageOf(document, block)));
                break;
            }
    }
    return stranded;
}

// The report of `data` laid out twice: as Qt paginates by itself, whose
// stranded headings are counted (the sweep does reach page feet), and by
// layOutPages, where each stranded heading is a failure said with `what`.
int strandedInBothLayouts(const core::report::ReportData& data, const std::string& what)
{
    const auto plain = ui::buildReportDocument(data);
    QTextFrameFormat margins = plain->rootFrame()->frameFormat();
    margins.setMargin(20.0 * 96.0 / 25.4);
    plain->rootFrame()->setFrameFormat(margins);
    plain->setPageSize(ui::a4Paper_px());
    const auto kept = ui::buildReportDocument(data);
    ui::layOutPages(*kept, ui::a4Paper_px());
    for (const auto& heading : strandedHeadings(*kept)) ADD_FAILURE() << what << ": " << heading;
    return static_cast<int>(strandedHeadings(*plain).size());
}

// strandedInBothLayouts over `base` with session notes a line (16 words)
// longer at a time, which walk each heading down through a page's foot.
int strandedOverGrowingNotes(const core::report::ReportData& base, const std::string& what)
{
    int strandedByQt = 0;
    for (int words = 0; words <= 1100; words += 16) {
        auto data = base;
        for (int k = 0; k < words; ++k) data.session.metadata.notes += "notes ";
        strandedByQt += strandedInBothLayouts(data, std::to_string(words) + " words of notes" + what);
    }
    return strandedByQt;
}

}  // namespace

TEST(ReportPages, AHeadingIsNeverLeftAtThePageFootWithoutItsTable)
{
    QTemporaryDir dir;
    const auto base = sessionWithNotes(dir);
    int strandedByQt = 0;
    for (int markers = 0; markers <= 70; markers += 2) {
        auto data = base;
        for (int k = 0; k < markers; ++k)
            data.events.push_back({0, "live", core::EventKind::Marker, 0.1 * k, 0.1 * k, 0, {}, {}, {}, "marker"});
        for (int k = 0; k < 4; ++k) data.annotations.push_back({0, 0.5 + k, "Grace", "a note", "", ""});
        strandedByQt += strandedInBothLayouts(data, std::to_string(markers) + " markers");
    }
    EXPECT_GT(strandedByQt, 0) << "no heading reached a page's foot: the sweep tests nothing";
}

// Issue 52 (fresh eyes): "Defect sites" and its line of introduction were
// left at a page's foot with the sites on the next page. Session notes a
// line longer at a time walk the heading down through the foot.
TEST(ReportPages, AHeadingAndItsLineOfIntroductionGoWithTheirTable)
{
    QTemporaryDir dir;
    const auto base = panelWithDefects(dir);
    EXPECT_GT(strandedOverGrowingNotes(base, ""), 0) << "no heading reached a page's foot: the sweep tests nothing";
    // Fresh eyes: with no defects, "None found." sat alone on the next page.
    auto none = base;
    none.events.clear();
    none.sites = {};
    EXPECT_GT(strandedOverGrowingNotes(none, ", no defects"), 0) << "no heading without a table reached a page's foot";
    // Sites the detector could not place: why, in a sentence.
    auto unplaced = base;
    unplaced.sites.method = "not placed: no whole stroke between two reversals";
    const QString text = ui::buildReportDocument(unplaced)->toPlainText();
    EXPECT_TRUE(text.contains(QStringLiteral("Positions not placed: "))) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("placed by not placed"))) << text.toStdString();
}
