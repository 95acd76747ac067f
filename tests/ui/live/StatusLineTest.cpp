// The status bar's recording field keeps a recording's losses after it is
// saved: "saved" alone would hide them.
#include "ui/live/StatusLine.h"

#include "core/storage/Recorder.h"
#include "support/MainWindowHelpers.h"

#include <QLabel>
#include <QMainWindow>
#include <QStatusBar>

#include <gtest/gtest.h>

using tactiscope::testing::child;

TEST(StatusLine, ASavedSessionStillSaysWhatItLost)
{
    QMainWindow window;
    auto* status = new tactiscope::ui::StatusLine(window.statusBar());
    const auto* recording = child<QLabel>(window, "recordingLabel");

    tactiscope::core::storage::RecorderStats stats;
    stats.samplesWritten = 6000;
    status->showSaved(7, stats);
    EXPECT_TRUE(recording->text().contains(QStringLiteral("Session 7 saved")));
    EXPECT_FALSE(recording->text().contains(QStringLiteral("lost")));
    EXPECT_TRUE(recording->styleSheet().isEmpty());

    stats.samplesDropped = 120;
    status->showSaved(7, stats);
    EXPECT_TRUE(recording->text().contains(QStringLiteral("120 lost"))) << recording->text().toStdString();
    EXPECT_FALSE(recording->styleSheet().isEmpty());  // in the alarm colour
}

TEST(StatusLine, NoDeviceIsSaidWhenTheNameIsEmpty)
{
    QMainWindow window;
    auto* status = new tactiscope::ui::StatusLine(window.statusBar());
    status->setDevice(QStringLiteral("Simulator (palpation)"));
    EXPECT_EQ(child<QLabel>(window, "deviceLabel")->text(), QStringLiteral("Simulator (palpation)"));
    status->setDevice({});
    EXPECT_EQ(child<QLabel>(window, "deviceLabel")->text(), QStringLiteral("No device"));
}
