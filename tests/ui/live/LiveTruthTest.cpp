// What the live window shows happened: every plot reads one clock — the
// recording's while recording, as the markers, dialogs and the stored
// session do, else the time since connect, saying which — an operator's
// marker is drawn where it was put, and a paused window moves as one
// under one banner.
#include "devices/session/LiveSession.h"
#include "devices/session/modes/PanelScanUnit.h"
#include "support/LiveUnit.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/panelscan/PanelScanView.h"
#include "ui/plot/LivePlotWidget.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QSplitter>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::devices::session::PanelScanUnit;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::liveUnit;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

namespace {

bool allRead(const QList<ui::LivePlotWidget*>& plots, const QString& label)
{
    return std::ranges::all_of(plots, [&](const ui::LivePlotWidget* p) { return p->timeAxisLabel() == label; });
}

}  // namespace

TEST(LiveTruth, ThePlotsReadTheRecordingsClockAndShowItsMarkers)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.resize(1366, 768);
    window.station().connectSource(liveSimulator());
    window.show();
    const auto plots = window.findChildren<ui::LivePlotWidget*>();
    ASSERT_GE(plots.size(), 2);
    ASSERT_TRUE(waitFor([&] { return allRead(plots, "Time since connect (s)"); }, 2000));
    runEventLoopFor(1500);  // the stream runs a while before the recording

    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    ASSERT_TRUE(window.startRecording());
    ASSERT_TRUE(waitFor([&] { return allRead(plots, "Recording time (s)"); }, 3000));
    // The recording's t = 0 is a moment of the stream some 1.5 s in.
    for (const auto* plot : plots) EXPECT_GT(plot->timeOrigin_s(), 1.0);
    runEventLoopFor(800);
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier);
    for (const auto* plot : plots) EXPECT_EQ(plot->markerCount(), 1u);
    runEventLoopFor(300);
    tactiscope::testing::saveScreenshot(window, QStringLiteral("live-marker"));

    // The panel's defects are drawn on the traces where they happened.
    auto* traces = qobject_cast<ui::LivePlotWidget*>(child<QSplitter>(window, "centreSplitter")->widget(0));
    ASSERT_NE(traces, nullptr);
    ASSERT_TRUE(waitFor([&] { return window.findChild<ui::PanelScanView*>()->defectCount() >= 1; }, 5000));
    EXPECT_TRUE(waitFor(
        [&] {
            return traces->eventCount() ==
                   static_cast<std::size_t>(window.findChild<ui::PanelScanView*>()->defectCount());
        },
        1000));
    EXPECT_EQ(traces->markerCount(), 1u) << "events are not the operator's markers";

    // The detector's best R is drawn against its threshold.
    ASSERT_TRUE(window.findChild<ui::PanelScanView*>()->lanes()->threshold(1).has_value());
    EXPECT_EQ(*window.findChild<ui::PanelScanView*>()->lanes()->threshold(1), 0.85);
    EXPECT_FALSE(window.findChild<ui::PanelScanView*>()->lanes()->threshold(0).has_value());

    // Paused: one banner, and the detector's lanes follow the main plot back.
    child<QAction>(window, "pauseAction")->trigger();
    int banners = 0;
    for (const auto* banner : window.findChildren<QLabel*>(QStringLiteral("pausedBanner")))
        banners += banner->isVisible() ? 1 : 0;
    EXPECT_EQ(banners, 1);
    ui::LivePlotWidget* main = traces;
    const double start_s = main->visibleTimeRange().first - 0.5;
    main->scrollTo(start_s);
    for (const auto* plot : plots) {
        if (!plot->isVisible()) continue;
        EXPECT_NEAR(plot->visibleTimeRange().first, start_s, 1e-9);
    }
    child<QAction>(window, "pauseAction")->trigger();

    window.stopRecording();
    EXPECT_TRUE(waitFor([&] { return allRead(plots, "Time since connect (s)"); }, 3000));
}

TEST(LiveTruth, TheKeyboardStartsOnTheTracesNotInADetectorSetting)
{
    ui::MainWindow window;
    window.station().connectSource(liveSimulator());
    window.show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    EXPECT_EQ(QApplication::focusWidget(), child<QSplitter>(window, "centreSplitter")->widget(0));
    QTest::keyClick(&window, Qt::Key_5);  // a stray key changes no setting
    EXPECT_EQ(liveUnit<PanelScanUnit>(*window.station().device()).detection()->settings().parameters.threshold, 0.85);
}
