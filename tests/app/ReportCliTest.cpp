// `tactiscope-cli report` on a real store written through the store API:
// the PDF's text (read back with pdftotext) holds the subject, the verdict
// and the event table; a range narrows it; bad input ends with exit 2 and
// one line; the page count printed is the written PDF's; a full disk is
// exit 1 and no file. The first page is rendered to PNG for a look
// (build/<preset>/screenshots/report-page1.png, or TACTISCOPE_SCREENSHOT_DIR).
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/PdfText.h"
#include "support/TmpfsMount.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;

namespace {

constexpr double kRate_hz = 500.0;

// Two cantilevers, 10 s: a slow swell with a dent-like bump at each defect.
QString makeStore(const QTemporaryDir& dir)
{
    const QString path = dir.filePath(QStringLiteral("r.tactiscope"));
    core::storage::SessionStore store(path.toStdString());
    core::storage::SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::PanelScan;
    metadata.subject = "door-42";
    metadata.operatorName = "Ada Lovelace";
    metadata.deviceModel = "Simulator — panel scan";
    metadata.profileJson = R"({"kind": "cantilever", "name": "Capsule probe 3"})";
    const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain},
                                                        {"b", "", core::ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, kRate_hz);
    std::vector<core::SampleBlock> blocks;
    for (std::uint64_t first = 0; first < 5000; first += 500) {
        core::SampleBlock block(2, 500, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
        for (std::size_t i = 0; i < 500; ++i) {
            const double t = static_cast<double>(first + i) / kRate_hz;
            const double bump = std::exp(-std::pow((t - 2.5) / 0.05, 2)) + std::exp(-std::pow((t - 7.1) / 0.05, 2));
            block.channel(0)[i] = 1e-4 * (std::sin(t) + bump);
            block.channel(1)[i] = 1e-4 * (std::cos(t) + bump);
        }
        blocks.push_back(std::move(block));
    }
    store.appendBlocks(id, blocks);
    store.addEvents(id, std::vector<core::storage::SessionEvent>{
                            {0, core::storage::kLiveAnalysis, tactiscope::core::EventKind::Defect, 2.5, 2.6, 1, 0.953,
                             0.052, 0.96, ""},
                            {0, core::storage::kLiveAnalysis, tactiscope::core::EventKind::Defect, 7.1, 7.2, -1, 0.912,
                             0.048, 1.04, ""},
                            {0,
                             core::storage::kLiveAnalysis,
                             tactiscope::core::EventKind::Marker,
                             4.0,
                             4.0,
                             0,
                             {},
                             {},
                             {},
                             "oil stain"},
                        });
    store.addAnnotation(id, {0, 9.0, "Grace", "second dent seen by eye", "", ""});
    store.endSession(id, tactiscope::core::SessionStatus::Complete);
    store.decideVerdict(id, {0, tactiscope::core::VerdictRole::Automatic, tactiscope::core::Verdict::DefectsFound, "",
                             "2026-11-21T14:12:00.000Z", "",
                             R"({"analysis":"live","defects":2,"sites":2,"threshold":0.85})"});
    return path;
}

}  // namespace

class ReportCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
        ASSERT_TRUE(m_dir.isValid());
        m_store = makeStore(m_dir);
    }
    QTemporaryDir m_dir;
    QString m_store;
};

TEST_F(ReportCli, ThePdfHoldsTheSubjectTheVerdictAndTheEventTable)
{
    const QString pdf = m_dir.filePath(QStringLiteral("report.pdf"));
    const auto result = runCli({QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"),
                                QStringLiteral("last"), QStringLiteral("--output"), pdf});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_TRUE(result.err.isEmpty()) << result.err.toStdString();
    EXPECT_TRUE(result.out.startsWith(QStringLiteral("session 1: "))) << result.out.toStdString();
    const QString text = pdfText(pdf);
    ASSERT_FALSE(text.isEmpty());
    const QLocale locale;
    for (const QString& expected :
         {QStringLiteral("door-42"), QStringLiteral("Ada Lovelace"), QStringLiteral("DEFECTS FOUND"),
          QStringLiteral("Capsule probe 3"), QStringLiteral("Defect sites (2)"), QStringLiteral("Crossings (2)"),
          QStringLiteral("automatic: defects found (live detector: 2 defects at 2 sites, threshold 0.85)"),
          QStringLiteral("From the events recorded live."), QStringLiteral("A then B"), QStringLiteral("B then A"),
          locale.toString(0.953, 'f', 3), locale.toString(0.912, 'f', 3), locale.toString(2.5, 'f', 3),
          locale.toString(7.1, 'f', 3), QStringLiteral("oil stain"), QStringLiteral("second dent seen by eye")})
        EXPECT_TRUE(text.contains(expected)) << expected.toStdString() << "\n" << text.toStdString();

    // The first page as a picture, for a person to look at.
    EXPECT_TRUE(tactiscope::testing::savePdfFirstPage(pdf, QStringLiteral("report-page1")));
}

TEST_F(ReportCli, ARangeReportsOnlyWhatLiesInIt)
{
    const QString pdf = m_dir.filePath(QStringLiteral("part.pdf"));
    const auto result = runCli({QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"),
                                QStringLiteral("1"), QStringLiteral("--output"), pdf, QStringLiteral("--from"),
                                QStringLiteral("5"), QStringLiteral("--to"), QStringLiteral("10")});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const QString text = pdfText(pdf);
    const QLocale locale;
    EXPECT_TRUE(text.contains(QStringLiteral("Crossings (1)"))) << text.toStdString();
    EXPECT_TRUE(text.contains(locale.toString(0.912, 'f', 3)));
    EXPECT_FALSE(text.contains(locale.toString(0.953, 'f', 3)));
    EXPECT_FALSE(text.contains(QStringLiteral("oil stain")));  // the marker at 4 s
}

TEST_F(ReportCli, ThePageCountIsTheWrittenDocuments)
{
    // 120 events make the event table run over several pages; before, the
    // count came from the document before layout and said "(1 page)".
    {
        core::storage::SessionStore store(m_store.toStdString());
        std::vector<core::storage::SessionEvent> events;
        for (int i = 0; i < 120; ++i)
            events.push_back({0, core::storage::kLiveAnalysis, tactiscope::core::EventKind::Defect, 0.05 * i,
                              0.05 * i + 0.01, 1, 0.9, 0.05, 1.0, ""});
        store.addEvents(1, events);
    }
    const QString pdf = m_dir.filePath(QStringLiteral("long.pdf"));
    const auto result = runCli({QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"),
                                QStringLiteral("1"), QStringLiteral("--output"), pdf});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto pages = pdfText(pdf).count(QLatin1Char('\f'));  // pdftotext ends each page with a form feed
    ASSERT_GT(pages, 1);
    EXPECT_TRUE(result.out.endsWith(QStringLiteral("(%1 pages)\n").arg(pages))) << result.out.toStdString();
}

TEST_F(ReportCli, AReportOntoAFullDiskFailsAndLeavesNoFile)
{
    // Before: "(1 page)", exit 0, and a truncated PDF.
    const tactiscope::testing::TmpfsMount disk("16k");  // a report with its plot is far larger
    if (!disk.mounted()) GTEST_SKIP() << tactiscope::testing::TmpfsMount::kSkipReason;
    const QString pdf = QString::fromStdString(disk.file("report.pdf"));
    const auto result = runCli({QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"),
                                QStringLiteral("1"), QStringLiteral("--output"), pdf});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(result.err.contains(QStringLiteral("No space left on device")) ||
                result.err.contains(QStringLiteral("disk full")))
        << result.err.toStdString();
    EXPECT_TRUE(result.out.isEmpty()) << result.out.toStdString();
    EXPECT_TRUE(
        QDir(QString::fromStdString(disk.path())).isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden))
        << "a partial or temporary file was left";
}

TEST_F(ReportCli, BadInputEndsWithExitTwoAndOneLine)
{
    const QString pdf = m_dir.filePath(QStringLiteral("never.pdf"));
    const QString missing = m_dir.filePath(QStringLiteral("missing.tactiscope"));
    const std::vector<QStringList> cases{
        {QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"), QStringLiteral("1")},
        {QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"), QStringLiteral("9"),
         QStringLiteral("--output"), pdf},
        {QStringLiteral("report"), QStringLiteral("--db"), missing, QStringLiteral("--session"), QStringLiteral("1"),
         QStringLiteral("--output"), pdf},
        {QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"), QStringLiteral("1"),
         QStringLiteral("--output"), pdf, QStringLiteral("--from"), QStringLiteral("8"), QStringLiteral("--to"),
         QStringLiteral("3")},
        {QStringLiteral("report"), QStringLiteral("--db"), m_store, QStringLiteral("--session"), QStringLiteral("1"),
         QStringLiteral("--output"), pdf, QStringLiteral("--from"), QStringLiteral("soon")},
    };
    for (const auto& arguments : cases) {
        const auto result = runCli(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_EQ(result.err.count(QLatin1Char('\n')), 1) << result.err.toStdString();
        EXPECT_TRUE(result.err.startsWith(QStringLiteral("tactiscope-cli: report: "))) << result.err.toStdString();
    }
    EXPECT_FALSE(QFileInfo::exists(pdf));
    // A folder that is not there is no bad input but a failure to write.
    const auto unwritable = runCli({QStringLiteral("report"), QStringLiteral("--db"), m_store,
                                    QStringLiteral("--session"), QStringLiteral("1"), QStringLiteral("--output"),
                                    m_dir.filePath(QStringLiteral("no/such/folder/r.pdf"))});
    EXPECT_EQ(unwritable.exitCode, 1);
}
