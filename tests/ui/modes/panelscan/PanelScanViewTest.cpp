// Panel-scan mode against the live simulator: defects appear in the list
// and in the session with the values the core's detector gives for the
// recorded samples; the verdict follows the count; parameters edited in the
// view reach the live detector at once, and impossible ones are refused
// with a reason.
#include "ui/modes/panelscan/PanelScanView.h"
#include "core/detector/LiveDetection.h"
#include "core/detector/OfflineDetection.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/session/modes/PanelScanUnit.h"
#include "support/LiveUnit.h"
#include "support/MainWindowHelpers.h"
#include "support/ReadyToRecord.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <qcustomplot.h>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::devices::session::PanelScanUnit;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::liveUnit;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

TEST(PanelScanView, DefectsAreListedStoredAndMatchTheCoreDetector)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("s.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);  // the smallest screen the workstation is made for
    window.station().connectSource(liveSimulator());
    window.show();
    EXPECT_LE(window.minimumSizeHint().width(), 1366);  // every mode's view fits it
    ASSERT_TRUE(window.findChild<ui::PanelScanView*>()->isVisible());
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    ASSERT_TRUE(window.startRecording());
    auto* table = child<QTableWidget>(*window.findChild<ui::PanelScanView*>(), "defectTable");
    runEventLoopFor(100);
    // Where the list stands before any defect: the count's and the banner's
    // texts change with every defect and must not move it (issue 37).
    const QRect before = table->geometry();
    // The simulated hand passes the dent about once a second, in both directions.
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 5; }, 10000));
    runEventLoopFor(300);
    EXPECT_EQ(table->geometry().x(), before.x());
    EXPECT_EQ(table->geometry().width(), before.width());
    // Every column whole, with the scroll bar there from the start.
    EXPECT_EQ(table->horizontalScrollBar()->maximum(), 0);
    tactiscope::testing::saveScreenshot(window, QStringLiteral("panel-scan"));
    tactiscope::testing::saveScreenshotAtSize(window, QStringLiteral("panel-scan"), {1920, 1080});
    const int listed = table->rowCount();
    EXPECT_EQ(window.findChild<ui::PanelScanView*>()->defectCount(), listed);
    // Every row is a crossing; the simulator's one dent is one site.
    const QString count = child<QLabel>(*window.findChild<ui::PanelScanView*>(), "defectCountLabel")->text();
    EXPECT_TRUE(count.contains("defects found")) << count.toStdString();
    EXPECT_TRUE(count.contains(QStringLiteral("defects at 1 site on this panel"))) << count.toStdString();
    window.stopRecording();
    auto* verdict = window.findChild<QDialog*>(QStringLiteral("verdictBox"));
    ASSERT_NE(verdict, nullptr);
    EXPECT_FALSE(verdict->isModal());
    // Issue 52: the dialog lists the panel it judges, whatever the live
    // list behind it shows by now: its one site, crossed as often as it says.
    const QString site = child<QLabel>(*verdict, "verdictFindings")->text();
    ASSERT_FALSE(site.contains(QLatin1Char('\n'))) << site.toStdString();  // one site
    const auto crossed =
        QRegularExpression(QStringLiteral("^Site 1: .*, (\\d+) A then B, (\\d+) B then A, ")).match(site);
    ASSERT_TRUE(crossed.hasMatch()) << site.toStdString();
    const int crossings = crossed.captured(1).toInt() + crossed.captured(2).toInt();
    const QString said = verdict->findChildren<QLabel*>().front()->text();
    EXPECT_TRUE(said.contains(QStringLiteral("%1 defects at 1 site found").arg(crossings))) << said.toStdString();
    {
        // The automatic verdict is stored before the operator answers.
        core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
        EXPECT_EQ(sessions.sessions().front().verdict, tactiscope::core::Verdict::DefectsFound);
    }
    // The operator overrides it, saying why.
    QTest::keyClicks(child<QLineEdit>(*verdict, "verdictNote"), QStringLiteral("oil drops, no dent"));
    tactiscope::testing::saveScreenshot(*verdict, QStringLiteral("verdict"));
    QTest::mouseClick(child<QPushButton>(*verdict, "passButton"), Qt::LeftButton);

    // The window writes off its thread: the operator's decision joins the
    // automatic one in the verdict's trail, with the name and the note.
    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_TRUE(waitFor([&] { return sessions.verdicts(sessions.sessions().front().id).size() == 2; }, 5000));
    const auto session = sessions.sessions().front();
    EXPECT_EQ(session.verdict, tactiscope::core::Verdict::Pass);
    const auto trail = sessions.verdicts(session.id);
    ASSERT_EQ(trail.size(), 2u);
    EXPECT_EQ(trail[0].role, tactiscope::core::VerdictRole::Automatic);
    EXPECT_EQ(trail[0].verdict, tactiscope::core::Verdict::DefectsFound);
    EXPECT_NE(trail[0].basisJson.find("\"analysis\":\"live\""), std::string::npos) << trail[0].basisJson;
    EXPECT_EQ(trail[1].role, tactiscope::core::VerdictRole::Operator);
    EXPECT_EQ(trail[1].verdict, tactiscope::core::Verdict::Pass);
    EXPECT_EQ(trail[1].decidedBy, "Ada");
    EXPECT_EQ(trail[1].note, "oil drops, no dent");
    const auto stored = sessions.events(session.id);
    ASSERT_GE(static_cast<int>(stored.size()), listed - 1);  // the last may still have been open
    // The core's detector over the recorded samples finds each stored defect
    // at the same time with the same order (after its first second, which
    // the live detector saw with the history before the recording).
    const auto a = sessions.readChannel(session.id, 0, 0, session.sampleCount);
    const auto b = sessions.readChannel(session.id, 1, 0, session.sampleCount);
    core::detector::DetectorParameters parameters;
    parameters.sampleInterval_s = 0.002;
    const auto outputs = core::detector::detectSeries({0.0, {a, b}, {}}, parameters);
    const auto expected = core::detector::segmentEvents(outputs, 0.002, 0.020, std::nullopt);
    int compared = 0;
    for (const auto& e : stored) {
        if (e.start_s < 1.0) continue;
        ++compared;
        const auto match = std::find_if(expected.begin(), expected.end(), [&](const auto& x) {
            return std::abs(x.start_s - e.start_s) < 0.0021 && x.direction == e.direction;
        });
        ASSERT_NE(match, expected.end()) << "defect at " << e.start_s << " s";
        EXPECT_NEAR(*e.peakR, match->peakR, 1e-3);  // binary32 samples vs the live doubles
    }
    EXPECT_GE(compared, 3);
}

TEST(PanelScanView, EditedParametersReachTheLiveDetectorAndBadOnesAreRefused)
{
    ui::MainWindow window;
    window.station().connectSource(liveSimulator());
    window.show();
    auto* view = window.findChild<ui::PanelScanView*>();
    auto* threshold = child<QDoubleSpinBox>(*view, "thresholdBox");
    threshold->setValue(0.999);
    runEventLoopFor(300);
    const std::size_t before =
        liveUnit<PanelScanUnit>(*window.station().device()).defects().size();  // whatever the old
                                                                               // threshold found
    // R stays below 0.999 on this probe: no defect for three seconds.
    runEventLoopFor(3000);
    EXPECT_EQ(liveUnit<PanelScanUnit>(*window.station().device()).defects().size(), before);
    // Lags from 200 to 100 ms cannot be: refused, with the reason shown.
    child<QDoubleSpinBox>(*view, "lagFromBox")->setValue(200);
    child<QDoubleSpinBox>(*view, "lagToBox")->setValue(100);
    auto* error = child<QLabel>(*view, "settingsError");
    EXPECT_TRUE(error->isVisible());
    EXPECT_TRUE(error->text().startsWith(QStringLiteral("Not applied"))) << error->text().toStdString();
    // Back to the paper's threshold: defects come again.
    child<QDoubleSpinBox>(*view, "lagFromBox")->setValue(2);
    child<QDoubleSpinBox>(*view, "lagToBox")->setValue(150);
    threshold->setValue(0.85);
    EXPECT_FALSE(error->isVisible());
    EXPECT_TRUE(
        waitFor([&] { return liveUnit<PanelScanUnit>(*window.station().device()).defects().size() > before; }, 5000));
}

// Issue 52: a panel recorded for less than the detector needs is not
// judged, and the live view says so where it says the verdict.
TEST(PanelScanView, APanelRecordedTooShortToJudgeIsSaidSoAndNotAskedAbout)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    tactiscope::testing::readyToRecord(window, dir.filePath("s.tactiscope"));
    runEventLoopFor(300);
    ASSERT_TRUE(window.startRecording());
    window.stopRecording();
    runEventLoopFor(2 * ui::LiveStation::kPoll_ms);
    const QString count = child<QLabel>(*window.findChild<ui::PanelScanView*>(), "defectCountLabel")->text();
    EXPECT_TRUE(count.contains(QStringLiteral("recorded on this panel — too short to judge ("))) << count.toStdString();
    EXPECT_EQ(window.findChild<QDialog*>(QStringLiteral("verdictBox")), nullptr);
}

// Issue 52 (fresh eyes): the live decision lane read "1 / 0 / -1" where the
// review and the report name its levels. It names them too, all in view.
TEST(PanelScanView, TheLiveDecisionLaneNamesItsLevelsAsTheReviewDoes)
{
    ui::MainWindow window;
    window.station().connectSource(liveSimulator());
    window.show();
    auto* lanes = window.findChild<ui::PanelScanView*>()->lanes();
    // Before the first defect the lane holds only "none": every level is in view all the same.
    ASSERT_TRUE(waitFor([&] { return lanes->laneCount() == 2 && lanes->valueRange(0).first < -1.0; }, 4000));
    EXPECT_GT(lanes->valueRange(0).second, 1.0);
    auto* plot = lanes->findChild<QCustomPlot*>();
    ASSERT_NE(plot, nullptr);
    auto* named = dynamic_cast<QCPAxisTickerText*>(plot->axisRect(0)->axis(QCPAxis::atLeft)->ticker().data());
    ASSERT_NE(named, nullptr);
    QStringList names;
    for (const auto& name : named->ticks()) names << name;
    EXPECT_EQ(names, QStringList({"B→A", "none", "A→B"}));
}
