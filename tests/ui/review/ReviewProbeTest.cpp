// A session from a probe that runs the detector itself (issue 38), in the
// review window: the probe's own defects on a row of the records' lane
// beside the recorded (workstation's) ones, listed as "the probe's own",
// the decision channels plotted, and the verdict's trail saying how far
// the two agreed.
#include "core/storage/SessionStore.h"
#include "support/EmulatorProcess.h"
#include "support/Screenshot.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"

#include <QLabel>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <gtest/gtest.h>

using namespace tactiscope;

TEST(ReviewProbe, TheProbesOwnDecisionsAreShownBesideTheRecordedOnesWithTheirAgreement)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("probe.tactiscope");
    const auto recorded = tactiscope::testing::recordEmulated(dir.path(), db, QStringLiteral("panel-scan"), 10,
                                                              {"--subject", "door-3"}, {"--probe-detector"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    QString error;
    std::unique_ptr<ui::ReviewWindow> window(ui::ReviewWindow::open(db, 1, nullptr, error));
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->resize(1366, 768);
    window->show();
    window->plot()->reload();

    int recordedDefects = 0, probeDefects = 0;
    for (int i = 0; i < window->recordList()->topLevelItemCount(); ++i) {
        const auto* item = window->recordList()->topLevelItem(i);
        if (item->text(1) != QStringLiteral("defect")) continue;
        recordedDefects += item->text(2) == QStringLiteral("recorded");
        if (item->text(2) != QStringLiteral("the probe's own")) continue;
        ++probeDefects;
        // The probe sends its lags: its events have them, as the workstation's do (52 ms here).
        EXPECT_TRUE(item->text(3).contains(QStringLiteral("lag 52 ms"))) << item->text(3).toStdString();
    }
    EXPECT_GT(recordedDefects, 3);
    EXPECT_EQ(probeDefects, recordedDefects);
    const QString header = window->findChild<QLabel*>(QStringLiteral("sessionHeader"))->text();
    EXPECT_TRUE(header.contains(QStringLiteral("probe and workstation agree on"))) << header.toStdString();
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-probe"));
}
