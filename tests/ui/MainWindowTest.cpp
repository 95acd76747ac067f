// The main window against the real-time simulator: live samples reach the
// plot and the status bar, and a screenshot shows what a user sees.
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/plot/LivePlotWidget.h"

#include <QLabel>
#include <QLocale>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::saveScreenshot;
using tactiscope::testing::waitFor;

namespace {

QString labelText(const ui::MainWindow& window, const char* name)
{
    const auto* label = window.findChild<QLabel*>(QString::fromLatin1(name));
    return label ? label->text() : QString();
}

}  // namespace

TEST(MainWindow, ShowsLiveSimulatorSamplesWithinTwoSeconds)
{
    ui::MainWindow window;
    window.station().connectSource(liveSimulator());
    window.show();
    ASSERT_TRUE(window.station().isConnected());
    EXPECT_TRUE(waitFor(
        [&] { return window.livePlot()->drawnPointCount(0) > 0 && window.livePlot()->drawnPointCount(1) > 0; }, 2000));
    EXPECT_EQ(labelText(window, "deviceLabel"), QStringLiteral("Simulator — panel scan"));
    EXPECT_EQ(window.windowTitle(), QStringLiteral("Tactiscope — Simulator — panel scan"));
    EXPECT_FALSE(window.windowIcon().pixmap(64, 64).isNull());
    EXPECT_TRUE(waitFor([&] { return labelText(window, "stateLabel") == QStringLiteral("Streaming"); }, 2000));
}

TEST(MainWindow, ReportsTheMeasuredRateAndSampleCount)
{
    ui::MainWindow window;
    window.resize(1200, 720);
    window.station().connectSource(liveSimulator());
    window.show();
    // The rate is measured over one second; give the traces a few strokes.
    ASSERT_TRUE(waitFor([&] { return labelText(window, "rateLabel").contains(QStringLiteral("Hz (nominal")); }, 5000));
    tactiscope::testing::runEventLoopFor(3000);
    EXPECT_GT(QLocale().toULongLong(labelText(window, "samplesLabel")), 1000u);
    EXPECT_EQ(labelText(window, "lostLabel"), QStringLiteral("0"));
    EXPECT_TRUE(labelText(window, "linkLabel").startsWith(QStringLiteral("Streaming · ")));
    EXPECT_EQ(window.livePlot()->samplesOverrun(), 0u);
    EXPECT_FALSE(saveScreenshot(window, QStringLiteral("main-window")).isEmpty());
}

TEST(MainWindow, DisconnectStopsTheStreamAndClearsThePlot)
{
    ui::MainWindow window;
    window.station().connectSource(liveSimulator());
    window.show();
    ASSERT_TRUE(waitFor([&] { return window.livePlot()->drawnPointCount(0) > 0; }, 2000));
    window.station().disconnectDevices();
    EXPECT_FALSE(window.station().isConnected());
    EXPECT_EQ(window.livePlot()->drawnPointCount(0), 0);
    EXPECT_EQ(window.windowTitle(), QStringLiteral("Tactiscope"));
    EXPECT_EQ(labelText(window, "deviceLabel"), QStringLiteral("No device"));
}
