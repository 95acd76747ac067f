// The review window on a long stored session (ten minutes of the simulated
// panel scan at 500 Hz, written by `tactiscope-cli simulate` and imported):
// the overview reads a small share of the sample chunks, a zoom shows the
// exact samples of the CSV, the records list jumps, notes are added, edited,
// deleted and brought back, re-analysis with other parameters finds the
// events `tactiscope-cli analyze` finds and saves them without touching the
// recorded ones, replay moves, and the exports write their files.
#include "ui/review/ReviewWindow.h"

#include "core/storage/SessionStore.h"
#include "ui/review/ReanalysisPanel.h"
#include "ui/review/ReviewPlot.h"

#include "support/CliRunner.h"
#include "support/MainWindowHelpers.h"
#include "support/PdfText.h"
#include "support/Screenshot.h"
#include "support/TextFiles.h"
#include "support/WaitFor.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QInputDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <memory>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;
using tactiscope::testing::waitFor;

namespace {

constexpr int kSeconds = 600;

class ReviewWindowTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_csv = m_dir.filePath("scan.csv");
        m_db = m_dir.filePath("s.tactiscope");
        ASSERT_EQ(
            runCli({"simulate", "--seconds", QString::number(kSeconds), "--seed", "3", "--output", m_csv}).exitCode, 0);
        ASSERT_EQ(runCli({"import", m_csv, "--db", m_db, "--subject", "door-5"}).exitCode, 0);
        core::storage::SessionStore store(m_db.toStdString());
        // Two recorded defects and an operator's marker, as a live session has.
        store.addEvents(
            1, std::vector<core::storage::SessionEvent>{
                   {0, "live", tactiscope::core::EventKind::Defect, 120.0, 120.1, 1, 0.91, 0.052, std::nullopt, ""},
                   {0, "live", tactiscope::core::EventKind::Defect, 300.5, 300.6, -1, 0.88, 0.050, std::nullopt, ""},
                   {0, "live", tactiscope::core::EventKind::Marker, 450.0, 450.0, 0, std::nullopt, std::nullopt,
                    std::nullopt, "scratch by the hem"}});
        QSettings().remove(QStringLiteral("review/reviewer"));  // no reviewer has typed a name yet
        QString error;
        m_window = ui::ReviewWindow::open(m_db, 1, nullptr, error);
        ASSERT_NE(m_window, nullptr) << error.toStdString();
        m_window->setAttribute(Qt::WA_DeleteOnClose, false);
        m_window->show();
        m_window->plot()->reload();
    }
    void TearDown() override { delete m_window; }

    QTemporaryDir m_dir;
    QString m_csv, m_db;
    ui::ReviewWindow* m_window = nullptr;
};

// Every sample of the stored session read once on a separate connection:
// what loading the whole session costs, in chunks.
std::uint64_t chunksOfWholeSession(const QString& db)
{
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = *store.session(1);
    for (std::size_t c = 0; c < store.channels(1).size(); ++c) store.readChannel(1, c, 0, session.sampleCount);
    return store.chunksRead();
}

QJsonArray cliEvents(const QStringList& arguments)
{
    const auto result = runCli(arguments);
    EXPECT_EQ(result.exitCode, 0) << result.err.toStdString();
    return QJsonDocument::fromJson(result.out.toUtf8()).object()["events"].toArray();
}

}  // namespace

TEST_F(ReviewWindowTest, TheOverviewReadsAFewChunksAndAZoomShowsTheExactSamples)
{
    const auto& overview = m_window->plot()->shown(0);
    EXPECT_FALSE(overview.exact);
    EXPECT_TRUE(m_window->plot()->shown(2).t_s.empty()) << "600 s of R would be computed for the overview";
    ASSERT_FALSE(overview.t_s.empty());
    EXPECT_LT(overview.t_s.front(), 1.0);
    EXPECT_GT(overview.t_s.back(), kSeconds - 1.0);
    const std::uint64_t whole = chunksOfWholeSession(m_db);
    const std::uint64_t read = m_window->store().chunksRead();
    EXPECT_LT(read * 10, whole) << read << " of " << whole << " chunks";
    RecordProperty("overview_chunks_read", std::to_string(read));
    RecordProperty("whole_session_chunks", std::to_string(whole));

    // 0.2 s at 500 Hz: the CSV's own rows 50000 to 50100, to the binary32 bit.
    m_window->plot()->setRange(100.0, 100.2);
    m_window->plot()->reload();
    const auto& zoomed = m_window->plot()->shown(1);
    ASSERT_TRUE(zoomed.exact);
    const QStringList lines = QString::fromUtf8(tactiscope::testing::readBytes(m_csv)).split(QLatin1Char('\n'));
    ASSERT_GE(zoomed.t_s.size(), 100u);
    for (std::size_t i = 0; i < zoomed.t_s.size(); ++i) {
        const QStringList row = lines[static_cast<qsizetype>(zoomed.firstIndex + i + 1)].split(QLatin1Char(','));
        EXPECT_NEAR(zoomed.t_s[i], row[0].toDouble(), 1e-6) << i;
        EXPECT_EQ(static_cast<float>(zoomed.low[i]), row[2].toFloat()) << i;
    }
    EXPECT_TRUE(m_window->plot()->readoutAt(100.1).contains(QStringLiteral("b: "))) << "readout names the channel";
    // The decision reads as its names (issue 37: before, "0.0000 … 0.0000" for "none").
    const QString readout = m_window->plot()->readoutAt(100.1);
    EXPECT_TRUE(QRegularExpression(QStringLiteral("Decision: (none|A→B|B→A)( … (none|A→B|B→A))?($| )"))
                    .match(readout)
                    .hasMatch())
        << readout.toStdString();
    // The detector's lanes follow the strains: too long a span to compute
    // over the whole session, exact when zoomed in (values in
    // DerivedPanelScanTest).
    EXPECT_EQ(m_window->plot()->laneNames(), (std::vector<std::string>{"a", "b", "best_r", "decision"}));
    const auto& bestR = m_window->plot()->shown(2);
    ASSERT_TRUE(bestR.exact);
    ASSERT_EQ(bestR.t_s.size(), zoomed.t_s.size());
    for (const double r : bestR.low) EXPECT_TRUE(r >= -1.0 && r <= 1.0) << r;
    // A correlation reads to three decimals (issue 52: "Best R: 0.0013789").
    EXPECT_TRUE(QRegularExpression(QStringLiteral("Best R: -?[01]\\.\\d{3} ")).match(readout).hasMatch())
        << readout.toStdString();

    // A still view reads nothing more (no reload on every repaint).
    const std::uint64_t settled = m_window->store().chunksRead();
    tactiscope::testing::runEventLoopFor(300);
    EXPECT_EQ(m_window->store().chunksRead(), settled);
}

TEST_F(ReviewWindowTest, TheListJumpsAndNotesAreAddedEditedDeletedAndBroughtBack)
{
    QTreeWidget* list = m_window->recordList();
    ASSERT_EQ(list->topLevelItemCount(), 3);
    QTreeWidgetItem* second = list->topLevelItem(1);
    EXPECT_EQ(second->text(1), QStringLiteral("defect"));
    EXPECT_TRUE(second->text(3).startsWith(QStringLiteral("site 2: B then A"))) << second->text(3).toStdString();
    m_window->jumpTo(second);
    EXPECT_NEAR(0.5 * (m_window->plot()->from_s() + m_window->plot()->to_s()), 300.55, 1e-6);
    EXPECT_LE(m_window->plot()->to_s() - m_window->plot()->from_s(), 2.0 + 1e-9);
    EXPECT_EQ(m_window->plot()->cursorTime(), 300.5);

    // A note needs a name: the first is refused and says where to type it.
    EXPECT_FALSE(m_window->addNoteAt(300.5, QStringLiteral("nameless")).isEmpty());
    auto* reviewer = child<QLineEdit>(*m_window, "reviewerEdit");
    EXPECT_TRUE(reviewer->hasFocus() || !m_window->isActiveWindow());
    EXPECT_TRUE(child<QLabel>(*m_window, "problemText")->text().contains("Reviewer box"));
    QTest::keyClicks(reviewer, QStringLiteral("Grace Hopper"));
    // A note at the pinned cursor, through the dialog as a reviewer types it.
    m_window->addNote();
    auto* dialog = m_window->findChild<QInputDialog*>(QStringLiteral("noteDialog"));
    ASSERT_NE(dialog, nullptr);
    // The time in the dialog's own text, which no title bar cuts.
    EXPECT_EQ(dialog->labelText(), QStringLiteral("Note at %1 s:").arg(QLocale().toString(300.5, 'f', 3)));
    dialog->setTextValue(QStringLiteral("dent confirmed by eye"));
    dialog->accept();
    ASSERT_EQ(list->topLevelItemCount(), 4);
    core::storage::SessionStore store(m_db.toStdString(), core::storage::Database::Access::ReadOnly);
    auto notes = store.annotations(1);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].time_s, 300.5);
    EXPECT_EQ(notes[0].text, "dent confirmed by eye");
    EXPECT_EQ(notes[0].author, "Grace Hopper");
    EXPECT_EQ(QSettings().value(QStringLiteral("review/reviewer")).toString(), QStringLiteral("Grace Hopper"));

    EXPECT_TRUE(m_window->editNote(notes[0].id, QStringLiteral("dent confirmed, 2 mm")).isEmpty());
    EXPECT_EQ(store.annotations(1)[0].text, "dent confirmed, 2 mm");
    EXPECT_TRUE(m_window->deleteNote(notes[0].id).isEmpty());
    EXPECT_TRUE(store.annotations(1).empty());
    EXPECT_EQ(list->topLevelItemCount(), 3);
    EXPECT_TRUE(m_window->undoDelete().isEmpty());
    notes = store.annotations(1);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].text, "dent confirmed, 2 mm");
    EXPECT_EQ(notes[0].time_s, 300.5);
}

TEST_F(ReviewWindowTest, AReviewersVerdictJoinsTheTrailWithTheNameAndTheNote)
{
    {
        core::storage::SessionStore store(m_db.toStdString());
        store.decideVerdict(1, {0, tactiscope::core::VerdictRole::Automatic, tactiscope::core::Verdict::DefectsFound,
                                "", "", "", R"({"analysis":"live","defects":2,"sites":2,"threshold":0.85})"});
    }
    child<QLineEdit>(*m_window, "reviewerEdit")->setText(QStringLiteral("Q. Engineer"));
    m_window->findChild<QAction*>(QStringLiteral("verdictAction"))->trigger();
    auto* box = m_window->findChild<QDialog*>(QStringLiteral("verdictBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->isModal());
    EXPECT_TRUE(child<QLabel>(*box, "verdictTrail")->text().startsWith("automatic: defects found (live detector: 2"));
    QTest::keyClicks(child<QLineEdit>(*box, "verdictNote"), QStringLiteral("bump is a marker pen line"));
    tactiscope::testing::saveScreenshot(*box, QStringLiteral("review-verdict"));
    QTest::mouseClick(child<QPushButton>(*box, "passButton"), Qt::LeftButton);

    core::storage::SessionStore store(m_db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.session(1)->verdict, tactiscope::core::Verdict::Pass);
    const auto trail = store.verdicts(1);
    ASSERT_EQ(trail.size(), 2u);
    EXPECT_EQ(trail[1].role, tactiscope::core::VerdictRole::Reviewer);
    EXPECT_EQ(trail[1].decidedBy, "Q. Engineer");
    EXPECT_EQ(trail[1].note, "bump is a marker pen line");
    const QString header = child<QLabel>(*m_window, "sessionHeader")->text();
    EXPECT_TRUE(header.contains("verdict <b>pass</b> (reviewer Q. Engineer changed it to pass"))
        << header.toStdString();
}

TEST_F(ReviewWindowTest, ReanalysisFindsWhatTheCliFindsAndSavesBesideTheRecordedEvents)
{
    ui::ReanalysisPanel* panel = qobject_cast<ui::ReanalysisPanel*>(m_window->account());
    ASSERT_NE(panel, nullptr);
    child<QDoubleSpinBox>(*panel, "thresholdSpin")->setValue(0.7);
    child<QDoubleSpinBox>(*panel, "lagStopSpin")->setValue(100.0);
    child<QDoubleSpinBox>(*panel, "holdSpin")->setValue(30.0);
    ASSERT_TRUE(panel->run());
    ASSERT_TRUE(waitFor([&] { return panel->hasResult() && !panel->isRunning(); }, 120000));

    const QJsonArray expected = cliEvents({"analyze", "--db", m_db, "--session", "1", "--json", "--threshold", "0.7",
                                           "--lags-ms", "2:100:2", "--hold-ms", "30"});
    const auto& found = panel->events();
    ASSERT_GT(expected.size(), 100);
    ASSERT_EQ(found.size(), static_cast<std::size_t>(expected.size()));
    for (std::size_t e = 0; e < found.size(); ++e) {
        const QJsonObject want = expected[static_cast<qsizetype>(e)].toObject();
        EXPECT_EQ(found[e].direction, want["direction"].toInt()) << e;
        EXPECT_NEAR(found[e].start_s, want["start_s"].toDouble(), 1e-9) << e;
        EXPECT_NEAR(found[e].end_s, want["end_s"].toDouble(), 1e-9) << e;
        EXPECT_NEAR(found[e].peakR, want["peak_r"].toDouble(), 1e-12) << e;
    }
    // Shown beside the recorded ones, in the list and the marker lane.
    QTreeWidget* list = m_window->recordList();
    EXPECT_EQ(list->topLevelItemCount(), 3 + expected.size());
    const auto recorded = list->findItems(QStringLiteral("recorded"), Qt::MatchExactly, 2);
    ASSERT_EQ(recorded.size(), 3);
    // Defects are named by their site (these two, without a speed, are not placed along the stroke).
    EXPECT_TRUE(recorded.front()->text(3).startsWith(QStringLiteral("site 1: A then B")))
        << recorded.front()->text(3).toStdString();
    m_window->jumpTo(recorded.front());
    m_window->plot()->reload();  // what the next event-loop turn reads
    tactiscope::testing::saveScreenshot(*m_window, QStringLiteral("review-window"));

    EXPECT_FALSE(panel->saveAs(QStringLiteral("live")).isEmpty());
    EXPECT_TRUE(panel->saveAs(QStringLiteral("threshold 0.7")).isEmpty());
    EXPECT_FALSE(panel->saveAs(QStringLiteral("threshold 0.7")).isEmpty()) << "a result is saved once";
    core::storage::SessionStore store(m_db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.events(1).size(), 3u);  // the recorded events untouched
    EXPECT_EQ(store.events(1, "threshold 0.7").size(), found.size());
}

TEST_F(ReviewWindowTest, AReanalysisShowsItsProgressAndCanBeCancelled)
{
    ui::ReanalysisPanel* panel = qobject_cast<ui::ReanalysisPanel*>(m_window->account());
    auto* progress = child<QProgressBar>(*panel, "analysisProgress");
    auto* cancel = child<QPushButton>(*panel, "cancelAnalysisButton");
    EXPECT_TRUE(progress->isHidden());
    EXPECT_TRUE(cancel->isHidden());

    // Cancelled at once: the worker stops after its first window of the
    // ten-minute session, and no result appears.
    ASSERT_TRUE(panel->run());
    EXPECT_FALSE(progress->isHidden());
    EXPECT_FALSE(cancel->isHidden());
    tactiscope::testing::saveScreenshot(*panel, QStringLiteral("reanalysis-running"));
    QTest::mouseClick(cancel, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !panel->isRunning(); }, 60000));
    EXPECT_FALSE(panel->hasResult());
    EXPECT_TRUE(child<QLabel>(*panel, "analysisStatus")->text().startsWith(QStringLiteral("Cancelled")));
    EXPECT_TRUE(progress->isHidden());
    EXPECT_FALSE(child<QPushButton>(*panel, "saveAnalysisButton")->isEnabled());

    // Run to the end: the bar moves through the windows and goes away.
    int highest = 0;
    ASSERT_TRUE(panel->run());
    ASSERT_TRUE(waitFor(
        [&] {
            highest = std::max(highest, progress->value());
            return !panel->isRunning();
        },
        120000));
    EXPECT_TRUE(panel->hasResult());
    EXPECT_GT(highest, 0);
    EXPECT_TRUE(progress->isHidden());
}

TEST_F(ReviewWindowTest, ReplayMovesThePlayheadAndTheView)
{
    m_window->plot()->setRange(10.0, 20.0);
    m_window->setReplaySpeed(10);
    m_window->play();
    ASSERT_TRUE(m_window->isPlaying());
    ASSERT_TRUE(waitFor([&] { return m_window->plot()->from_s() > 10.0; }, 20000)) << "the view follows the playhead";
    m_window->pause();
    EXPECT_FALSE(m_window->isPlaying());

    // Space plays and pauses even with the speed box in focus (it swallowed
    // the key), and the button keeps its width as "Play" flips to "Pause".
    auto* speed = child<QSpinBox>(*m_window, "replaySpeed");
    m_window->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(m_window));
    speed->setFocus();
    auto* button = m_window->findChild<QToolBar*>()->widgetForAction(m_window->findChild<QAction*>("playAction"));
    ASSERT_NE(button, nullptr);
    const int width = button->width();
    QTest::keyClick(speed, Qt::Key_Space);
    EXPECT_TRUE(m_window->isPlaying());
    tactiscope::testing::runEventLoopFor(50);
    EXPECT_EQ(button->width(), width);
    QTest::keyClick(speed, Qt::Key_Space);
    EXPECT_FALSE(m_window->isPlaying());
}

TEST_F(ReviewWindowTest, ExportsTheReportThePlotAndTheRangeShownAsCsv)
{
    const QString pdf = m_dir.filePath("report.pdf");
    ASSERT_TRUE(m_window->exportReport(pdf).isEmpty());
    const QString text = pdfText(pdf);
    if (!text.isEmpty()) {
        EXPECT_TRUE(text.contains(QStringLiteral("door-5")));
        EXPECT_TRUE(text.contains(QStringLiteral("B then A")));
    }

    // A replay's playhead is on the screen but not in the saved image.
    m_window->plot()->setPlayhead(0.5 * (m_window->plot()->from_s() + m_window->plot()->to_s()));
    tactiscope::testing::runEventLoopFor(100);  // the queued replot
    const auto playheadPixels = [](const QImage& image) {
        int count = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);  // the playhead's red, antialiased
                count += c.red() > 150 && c.green() < 110 && c.blue() < 130 && c.red() - c.green() > 80;
            }
        }
        return count;
    };
    ASSERT_GT(playheadPixels(m_window->plot()->grab().toImage()), 50);
    for (const char* name : {"plot.png", "plot.svg"}) {
        const QString image = m_dir.filePath(QString::fromLatin1(name));
        ASSERT_TRUE(m_window->savePlot(image).isEmpty());
        EXPECT_GT(QFile(image).size(), 1000) << name;
    }
    EXPECT_EQ(playheadPixels(QImage(m_dir.filePath("plot.png"))), 0);
    EXPECT_GT(playheadPixels(m_window->plot()->grab().toImage()), 50) << "the screen keeps it";

    // 2 s shown at 500 Hz, from 10.001 s (sample 5000.5) to 12.001 s
    // (6000.5), rounded outwards: samples 5000 to 6001, as simulated.
    m_window->plot()->setRange(10.001, 12.001);
    const QString csv = m_dir.filePath("range.csv");
    ASSERT_TRUE(m_window->exportCsv(csv, true).isEmpty());
    const QStringList rows = QString::fromUtf8(tactiscope::testing::readBytes(csv)).trimmed().split(QLatin1Char('\n'));
    const QStringList all = QString::fromUtf8(tactiscope::testing::readBytes(m_csv)).split(QLatin1Char('\n'));
    ASSERT_EQ(rows.size(), 1 + 1002);
    for (qsizetype r = 1; r < rows.size(); ++r) {
        const QStringList got = rows[r].split(QLatin1Char(',')), want = all[5000 + r].split(QLatin1Char(','));
        EXPECT_EQ(got[1].toFloat(), want[1].toFloat()) << r;
        EXPECT_EQ(got[2].toFloat(), want[2].toFloat()) << r;
    }
    const auto meta = QJsonDocument::fromJson(tactiscope::testing::readBytes(m_dir.filePath("range.meta.json")));
    EXPECT_EQ(meta["exported_range"]["first_index"].toInt(), 5000);
    EXPECT_EQ(meta["exported_range"]["count"].toInt(), 1002);
}

TEST_F(ReviewWindowTest, ASessionDeletedUnderTheWindowIsSaidNotThrown)
{
    // Another station, or the CLI, deletes the session while it is shown.
    const auto before = m_window->plot()->shown(0).t_s.size();
    core::storage::SessionStore(m_db.toStdString()).deleteSession(1);
    m_window->plot()->setRange(10.0, 20.0);
    EXPECT_NO_THROW(m_window->plot()->reload());
    const auto* problem = child<QLabel>(*m_window, "problemText");
    EXPECT_TRUE(problem->isVisibleTo(m_window));
    EXPECT_TRUE(problem->text().contains(QStringLiteral("cannot be read"))) << problem->text().toStdString();
    EXPECT_EQ(m_window->plot()->shown(0).t_s.size(), before);  // the lanes keep what they showed
}
