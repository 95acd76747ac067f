// `tactiscope-cli shunt-check` against `emulate`, both real processes over a
// real pty: the emulated probe's quarter bridges (350 Ω gauges, GF 2, a
// 100 kΩ shunt: devices/simulator/ShuntedBridges.h) step by
// y/GF = −350/100350/2 = −1743.9 µε, computed here by hand; the check passes
// for the gauges' true factor and fails for 2.1 (expected −1660.9 µε, +5.0 %)
// and for a half bridge (expected y/((2 + y)·GF) = −873.5 µε); the result is
// kept in the store's calibration history; an older probe that answers
// nothing, and a probe that moves during the check, are refused.
#include "core/calibration/CalibrationRecord.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::runCli;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

TEST(ShuntCheckCli, TheEmulatedBridgePassesForItsGaugeFactorAndFailsForAnotherAndTheResultIsKept)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("checks.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-rest", "--seed", "5"}));
    const auto right = runCli(
        {"shunt-check", "--port", link, "--channel", "a", "--gauge-factor", "2", "--db", db, "--operator", "Ada"});
    const auto wrong = runCli({"shunt-check", "--port", link, "--channel", "b", "--gauge-factor", "2.1", "--db", db});
    const auto half = runCli({"shunt-check", "--port", link, "--channel", "a", "--bridge", "half"});
    stopEmulator(emulator);

    EXPECT_EQ(right.exitCode, 0) << right.err.toStdString();
    // The ± to two digits, never "± 0.0" for a quiet bridge, and the
    // expected step beside it to the same decimals.
    const auto line = QRegularExpression(QStringLiteral("^Shunt check a: expected (-[0-9]+\\.([0-9]+)) µε, measured "
                                                        "-[0-9]+\\.([0-9]+) ± (0\\.0*[1-9][0-9]?|[1-9][0-9.]*) µε, "))
                          .match(right.out);
    ASSERT_TRUE(line.hasMatch()) << right.out.toStdString();
    EXPECT_NEAR(line.captured(1).toDouble(), -1743.895, 0.006);  // y/GF, y = -350/100350, by hand
    EXPECT_EQ(line.captured(2).size(), line.captured(3).size()) << right.out.toStdString();
    // The probe's replies to the shunt commands take sequence numbers of
    // their own: no frame was skipped.
    EXPECT_FALSE(right.err.contains(QStringLiteral("skipped"))) << right.err.toStdString();
    EXPECT_TRUE(right.out.contains(QStringLiteral("(tolerance 1 %): PASS"))) << right.out.toStdString();
    EXPECT_EQ(wrong.exitCode, 1);
    EXPECT_TRUE(wrong.out.contains(QRegularExpression(QStringLiteral("expected -1660\\.(9|8[5-9])[0-9]* µε"))))
        << wrong.out.toStdString();
    EXPECT_TRUE(wrong.out.contains(QStringLiteral("deviation +5.00 %"))) << wrong.out.toStdString();
    EXPECT_TRUE(wrong.out.contains(QStringLiteral("FAIL")));
    EXPECT_EQ(half.exitCode, 1);
    EXPECT_TRUE(half.out.contains(QRegularExpression(QStringLiteral("expected -873\\.(5|4[6-9])[0-9]* µε"))))
        << half.out.toStdString();

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto history = store.calibrations();
    ASSERT_EQ(history.size(), 2u);
    for (const auto& stored : history) EXPECT_EQ(stored.record.kind, core::calibration::kShuntCheckKind);
    const auto& first = history[0].record.sensorName == "EMU-5 a" ? history[0].record : history[1].record;
    const auto& second = &first == &history[0].record ? history[1].record : history[0].record;
    EXPECT_EQ(first.sensorName, "EMU-5 a");
    EXPECT_EQ(first.operatorName, "Ada");
    EXPECT_EQ(first.value("shunt_passed"), 1.0);
    EXPECT_NEAR(*first.value("shunt_expected_ue"), -1743.9, 0.05);
    EXPECT_NEAR(*first.value("shunt_deviation_percent"), 0.0, 0.05);
    EXPECT_EQ(first.value("gauge_resistance_ohm"), 350.0);
    EXPECT_EQ(first.value("shunt_resistance_ohm"), 100e3);
    EXPECT_EQ(first.value("bridge_active_gauges"), 1.0);
    EXPECT_EQ(second.sensorName, "EMU-5 b");
    EXPECT_EQ(second.value("shunt_passed"), 0.0);
    EXPECT_NEAR(*second.value("shunt_deviation_percent"), 5.0, 0.05);
}

TEST(ShuntCheckCli, AnOlderProbeAndAMovingOneAreRefusedWithTheReason)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    QProcess older;
    ASSERT_TRUE(startEmulator(older, link, {"--scenario", "panel-rest", "--no-shunt"}));
    const auto silent = runCli({"shunt-check", "--port", link, "--channel", "a"});
    stopEmulator(older);
    EXPECT_EQ(silent.exitCode, 1);
    EXPECT_TRUE(silent.err.contains(QStringLiteral("did not answer the shunt command: it cannot switch a shunt")))
        << silent.err.toStdString();

    QProcess moving;
    ASSERT_TRUE(startEmulator(moving, link, {"--scenario", "panel-scan"}));
    const auto moved = runCli({"shunt-check", "--port", link, "--channel", "a"});
    stopEmulator(moving);
    EXPECT_EQ(moved.exitCode, 1);
    EXPECT_TRUE(moved.err.contains(QStringLiteral("hold the probe still"))) << moved.err.toStdString();

    QProcess capacitive;
    ASSERT_TRUE(startEmulator(capacitive, link, {"--scenario", "capacitive-weights"}));
    const auto noBridge = runCli({"shunt-check", "--port", link, "--channel", "capacitance"});
    stopEmulator(capacitive);
    EXPECT_EQ(noBridge.exitCode, 1);
    EXPECT_TRUE(noBridge.err.contains(QStringLiteral("has no bridge to shunt"))) << noBridge.err.toStdString();
}

// The check's numbers keep to their ranges (core/NumberRanges.h) before any
// port is opened: before, --tolerance 1e300 passed a full bridge reading a
// quarter bridge's step (+299 %) and stored it as a pass.
TEST(ShuntCheckCli, NumbersOutsideTheirRangesAreRefusedNamingTheRange)
{
    const auto refused = [](const QStringList& options, const QString& why) {
        const auto result = runCli(QStringList{"shunt-check", "--port", "/nonexistent", "--channel", "a"} + options);
        EXPECT_EQ(result.exitCode, 2) << options.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(why)) << result.err.toStdString();
    };
    refused({"--tolerance", "1e300"}, QStringLiteral("--tolerance must be a number from 0.01 to 50 %, not '1e300'"));
    refused({"--tolerance", "0"}, QStringLiteral("--tolerance must be a number from 0.01 to 50 %"));
    refused({"--gauge-factor", "-2"}, QStringLiteral("--gauge-factor must be a number from 0.1 to 200"));
    refused({"--shunt-ohms", "x"}, QStringLiteral("--shunt-ohms must be a number from 1 to 1000000000 Ω, not 'x'"));
}
