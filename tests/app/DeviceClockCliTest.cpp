// A device's clock against the host's, end to end (issue 40): `emulate`
// with a crystal a known number of ppm off, over a real pty, and `record`
// says how far off it ran, from its blocks' stamps and arrivals
// (core/timing/ClockAlignment). The pty's delivery jitter (tenths of a
// millisecond) over 20 s allows a few ppm; 10 ppm is the tolerance.
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using tactiscope::testing::recordEmulated;
using tactiscope::testing::runCli;

namespace {

// "device clock: 80.3 ppm slow against …" → +80.3 (fast: negative); NaN without one.
double statedDrift_ppm(const QString& err)
{
    const auto match =
        QRegularExpression(QStringLiteral("device clock: ([0-9.]+)(?: ± [0-9.]+)? ppm (slow|fast)")).match(err);
    if (!match.hasMatch()) return std::nan("");
    return match.captured(1).toDouble() * (match.captured(2) == QStringLiteral("slow") ? 1.0 : -1.0);
}

}  // namespace

TEST(DeviceClockCli, ACrystalEightyPpmSlowIsSaidAsSuch)
{
    QTemporaryDir dir;
    const auto result = recordEmulated(dir.path(), dir.filePath("t.tactiscope"), QStringLiteral("panel-scan"), 20, {},
                                       {"--drift-ppm", "80"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_NEAR(statedDrift_ppm(result.err), 80.0, 10.0) << result.err.toStdString();
}

TEST(DeviceClockCli, ACrystalAHundredPpmFastWithItsClockAlreadyRunningIsSaidAsSuch)
{
    QTemporaryDir dir;
    const auto result = recordEmulated(dir.path(), dir.filePath("t.tactiscope"), QStringLiteral("panel-scan"), 20, {},
                                       {"--drift-ppm", "-100", "--clock-offset", "1000"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_NEAR(statedDrift_ppm(result.err), -100.0, 10.0) << result.err.toStdString();
}

TEST(DeviceClockCli, AShortRecordingSaysNothingOfTheClockAndBadCrystalsAreRefused)
{
    QTemporaryDir dir;
    const auto shortOne = recordEmulated(dir.path(), dir.filePath("t.tactiscope"), QStringLiteral("panel-scan"), 3, {},
                                         {"--drift-ppm", "80"});
    ASSERT_EQ(shortOne.exitCode, 0) << shortOne.err.toStdString();
    EXPECT_FALSE(shortOne.err.contains(QStringLiteral("device clock"))) << "3 s cannot tell 80 ppm";
    for (const QStringList& bad : {QStringList{"--drift-ppm", "2000"}, QStringList{"--drift-ppm", "x"},
                                   QStringList{"--clock-offset", "-1"}, QStringList{"--clock-offset", "5000"}}) {
        const auto result = runCli(QStringList{"emulate", "--link", dir.filePath("p")} + bad);
        EXPECT_EQ(result.exitCode, 2) << bad.join(' ').toStdString();
    }
}
