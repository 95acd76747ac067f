// Who decided a panel's verdict, through the CLI: `sessions verdict` adds a
// reviewer's decision with the name and the note, `sessions show` and the
// report show the whole trail; `report --analysis NAME` reports a
// re-analysis saved with `analyze --save` and says which analysis it shows.
#include "support/CliRunner.h"
#include "support/PdfText.h"

#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;

namespace {

class VerdictCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
        ASSERT_TRUE(m_dir.isValid());
        // 8 s of the simulator's scan, imported: no live events, as from another program.
        const QString csv = m_dir.filePath("scan.csv");
        ASSERT_EQ(runCli({"simulate", "--seconds", "8", "--seed", "3", "--output", csv}).exitCode, 0);
        ASSERT_EQ(runCli({"import", csv, "--db", m_db, "--subject", "door-5"}).exitCode, 0);
    }

    // The report's text on one line, as a person reads across its wrapping.
    QString report(const QStringList& extra = {})
    {
        const QString pdf = m_dir.filePath("r.pdf");
        const auto result = runCli(QStringList{"report", "--db", m_db, "--session", "last", "--output", pdf} + extra);
        EXPECT_EQ(result.exitCode, 0) << result.err.toStdString();
        return pdfText(pdf).simplified();
    }

    QTemporaryDir m_dir;
    QString m_db = m_dir.filePath("s.tactiscope");
};

}  // namespace

TEST_F(VerdictCli, AReanalysisSavedByAnalyzeIsReportedWithItsDefectSites)
{
    const auto saved = runCli({"analyze", "--db", m_db, "--session", "last", "--threshold", "0.8", "--save", "t0.8"});
    ASSERT_EQ(saved.exitCode, 0) << saved.err.toStdString();
    const auto json = runCli({"analyze", "--db", m_db, "--session", "last", "--threshold", "0.8", "--json"});
    const qsizetype events = json.out.count(QStringLiteral("\"direction\""));
    ASSERT_GE(events, 6);

    // Before: "Defects (0) None found" whatever was saved.
    const QString recorded = report();
    EXPECT_TRUE(recorded.contains("Defect sites (0) From the events recorded live. None found."))
        << recorded.toStdString();
    const QString reanalysed = report({"--analysis", "t0.8"});
    EXPECT_TRUE(reanalysed.contains("From the saved re-analysis \"t0.8\".")) << reanalysed.toStdString();
    EXPECT_TRUE(reanalysed.contains(QStringLiteral("Crossings (%1)").arg(events))) << reanalysed.toStdString();
    // The simulator's one dent, crossed on every pass, is one site.
    EXPECT_TRUE(reanalysed.contains("Defect sites (1)")) << reanalysed.toStdString();

    const auto unknown = runCli(
        {"report", "--db", m_db, "--session", "last", "--output", m_dir.filePath("x.pdf"), "--analysis", "t0.9"});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(unknown.err.contains("has no analysis 't0.9' (it has: live, t0.8)")) << unknown.err.toStdString();
}

TEST_F(VerdictCli, AReviewersVerdictJoinsTheTrailWithTheNameAndTheNote)
{
    const auto decided = runCli({"sessions", "--db", m_db, "verdict", "last", "defects-found", "--by", "Ada"});
    ASSERT_EQ(decided.exitCode, 0) << decided.err.toStdString();
    EXPECT_TRUE(decided.out.startsWith("Session 1: reviewer Ada decided: defects found, "))
        << decided.out.toStdString();
    const auto changed = runCli({"sessions", "--db", m_db, "verdict", "last", "pass", "--by", "Q. Engineer", "--note",
                                 "bump is a marker pen line"});
    ASSERT_EQ(changed.exitCode, 0) << changed.err.toStdString();
    EXPECT_TRUE(changed.out.contains("reviewer Q. Engineer changed it to pass")) << changed.out.toStdString();

    const auto list = runCli({"sessions", "--db", m_db, "list", "--verdict", "pass"});
    EXPECT_TRUE(list.out.contains("door-5")) << list.out.toStdString();
    // The list shows each session's verdict in a column of its own.
    EXPECT_TRUE(list.out.contains(QRegularExpression(QStringLiteral("\\bverdict +duration\\b"))))
        << list.out.toStdString();
    EXPECT_TRUE(list.out.contains(QRegularExpression(QStringLiteral("complete +pass +[0-9.]+ s  door-5"))))
        << list.out.toStdString();
    // The list filter takes the verdict as the verdict command writes it (and as stored).
    for (const char* word : {"defects-found", "defects found"}) {
        const auto none = runCli({"sessions", "--db", m_db, "list", "--verdict", word});
        EXPECT_EQ(none.exitCode, 0) << word << ": " << none.err.toStdString();
        EXPECT_FALSE(none.out.contains("door-5")) << none.out.toStdString();
    }
    EXPECT_EQ(runCli({"sessions", "--db", m_db, "list", "--verdict", "defect"}).exitCode, 2);
    const auto show = runCli({"sessions", "--db", m_db, "show", "1"});
    EXPECT_TRUE(show.out.contains("reviewer Ada decided: defects found")) << show.out.toStdString();
    EXPECT_TRUE(show.out.contains("\"bump is a marker pen line\"")) << show.out.toStdString();

    const QString text = report();
    EXPECT_TRUE(text.contains("Verdict: PASS")) << text.toStdString();
    EXPECT_TRUE(text.contains("reviewer Ada decided: defects found")) << text.toStdString();
    EXPECT_TRUE(text.contains("reviewer Q. Engineer changed it to pass")) << text.toStdString();
    EXPECT_TRUE(text.contains("\"bump is a marker pen line\"")) << text.toStdString();
}

TEST_F(VerdictCli, AVerdictWithoutANameOrOfAnotherModeIsRefused)
{
    const QString palpation = m_dir.filePath("p.csv");
    ASSERT_EQ(runCli({"simulate", "--scenario", "palpation", "--seconds", "2", "--output", palpation}).exitCode, 0);
    ASSERT_EQ(runCli({"import", palpation, "--db", m_db, "--mode", "palpation"}).exitCode, 0);
    const struct {
        QStringList arguments;
        const char* message;
    } cases[] = {
        {{"sessions", "--db", m_db, "verdict", "1", "pass"}, "verdict needs --by NAME"},
        {{"sessions", "--db", m_db, "verdict", "1", "pass", "--by", "  "}, "verdict needs --by NAME"},
        {{"sessions", "--db", m_db, "verdict", "1", "--by", "Ada"}, "verdict needs a session and a verdict"},
        {{"sessions", "--db", m_db, "verdict", "1", "fine", "--by", "Ada"},
         "must be pass or defects-found, not 'fine'"},
        {{"sessions", "--db", m_db, "verdict", "2", "pass", "--by", "Ada"}, "is a palpation session"},
        {{"sessions", "--db", m_db, "verdict", "9", "pass", "--by", "Ada"}, "there is no session '9'"},
    };
    for (const auto& c : cases) {
        const auto result = runCli(c.arguments);
        EXPECT_EQ(result.exitCode, 2) << c.arguments.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(QString::fromUtf8(c.message))) << result.err.toStdString();
    }
    const auto show = runCli({"sessions", "--db", m_db, "show", "1"});
    EXPECT_TRUE(show.out.contains(QStringLiteral("verdict           —"))) << show.out.toStdString();
}
