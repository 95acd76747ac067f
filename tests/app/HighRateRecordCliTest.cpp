// The fastest stream issue 40 asks for, end to end: `emulate` at 16
// channels × 10 kHz behind a real pty (650 KB/s of TSP/1 frames, the pty
// holding about 4 KB of them: a few milliseconds), recorded for 20 s by
// `record` with the panel scan's analysis running. Every sample reaches
// the store: none lost, no broken frame. (Before the port was read on a
// thread of its own, the host's first 160 ms of opening the store and
// building the processors cost a frame at every start.)
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using tactiscope::testing::recordEmulated;

TEST(HighRateRecordCli, SixteenChannelsAtTenKilohertzReachTheStoreWithNoSampleLost)
{
    QTemporaryDir dir;
    const auto result = recordEmulated(dir.path(), dir.filePath("s.tactiscope"), QStringLiteral("panel-scan"), 20, {},
                                       {"--channels", "16", "--rate", "10000"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto match =
        QRegularExpression(
            QStringLiteral("(\\d+) samples per channel, (\\d+) lost, (\\d+) CRC errors? \\(16 channels at "
                           "10000 Hz"))
            .match(result.out);
    ASSERT_TRUE(match.hasMatch()) << result.out.toStdString();
    EXPECT_EQ(match.captured(2).toInt(), 0) << result.out.toStdString();
    EXPECT_EQ(match.captured(3).toInt(), 0) << result.out.toStdString();
    // 20 s at 10 kHz, give or take the start's and the stop's frames.
    EXPECT_NEAR(match.captured(1).toDouble(), 200000.0, 2000.0) << result.out.toStdString();
}
