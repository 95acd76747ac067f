// A capacitive beam calibrated against a reference load cell on a second
// device (issue 40), end to end: two `emulate` processes behind real ptys —
// the beam (capacitive-calibration, its crystal 80 ppm slow, its clock at
// 0.5 s) and a load cell (its zero 20 µN) — feel one sweep begun at one
// instant of the host's steady clock; `record --port beam=… --port
// load-cell=…` stores them as one session; `calibrate-capacitive --session`
// pairs them on the session's clock. Its sensitivity must agree with the
// weights' calibration of the same simulated beam (the paper's procedure,
// `simulate capacitive-weights`) within the two stated uncertainties
// (k = 2), and what the emulators were told is found again: the load
// cell's zero, the sweep's peak (150 mgf) and its one turn. A session
// without a reference force, a channel named that is not there and the
// options' misuse are refused with the reason.
#include "devices/SteadyClock.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using tactiscope::testing::jsonOf;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

constexpr double kMilligramForce_n = 9.80665e-6;

}  // namespace

TEST(ReferenceSweepCli, TheBeamCalibratedAgainstALoadCellOnAnotherDeviceAgreesWithItsWeights)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    // 12 s unloaded (C0), the 40 s sweep, 12 s unloaded (the drift).
    const QString sweepAt = QString::number(tactiscope::devices::steadySeconds() + 12.0, 'f', 6);
    QProcess beam, cell;
    ASSERT_TRUE(startEmulator(beam, dir.filePath("beam"),
                              {"--scenario", "capacitive-calibration", "--rate", "500", "--seed", "3", "--drift-ppm",
                               "80", "--clock-offset", "0.5", "--sweep-at", sweepAt}));
    ASSERT_TRUE(startEmulator(cell, dir.filePath("cell"),
                              {"--scenario", "load-cell", "--seed", "4", "--drift-ppm", "-50", "--sweep-at", sweepAt}));
    const auto recorded = runCli({"record", "--port", "beam=" + dir.filePath("beam"), "--port",
                                  "load-cell=" + dir.filePath("cell"), "--seconds", "64", "--db", db});
    stopEmulator(beam);
    stopEmulator(cell);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const auto session = QString::number(sessionIdIn(recorded.out));

    const auto swept =
        runCli({"calibrate-capacitive", "--db", db, "--session", session, "--json", "--baseline-wander", "0.0002"});
    ASSERT_EQ(swept.exitCode, 0) << swept.err.toStdString();
    const QJsonObject s = jsonOf(swept);
    EXPECT_EQ(s["reference"].toString(), "load-cell/force");
    EXPECT_EQ(s["capacitance"].toString(), "beam/capacitance");
    EXPECT_NEAR(s["reference_zero_n"].toDouble(), 20e-6, 0.05e-6);
    EXPECT_NEAR(s["sweep_span_n"].toDouble(), 150.0 * kMilligramForce_n, 3e-6);
    EXPECT_EQ(s["sweep_turns"].toInt(), 1);
    EXPECT_EQ(s["points"].toInt(), 21);  // ten bins each way and the zero
    EXPECT_GT(s["paired_samples"].toInt(), 30000);
    ASSERT_TRUE(s["clock_u_s"].isDouble()) << swept.out.toStdString();
    EXPECT_LT(s["clock_u_s"].toDouble(), 1e-3);
    // 1.47 mN in 20 s: 74 µN/s, so the clocks shift a pairing by far less
    // than the load cell's 0.3 µN of noise.
    EXPECT_LT(s["timing_force_u_n"].toDouble(), 0.3e-6);

    const QString weights = dir.filePath("weights.csv");
    const auto simulated = runCli(
        {"simulate", "--scenario", "capacitive-weights", "--seconds", "252", "--seed", "3", "--output", weights});
    ASSERT_EQ(simulated.exitCode, 0) << simulated.err.toStdString();
    // The simulator's baseline stability (its random walk), as a profile would state it.
    const auto placed = runCli({"calibrate-capacitive", weights, "--json", "--baseline-wander", "0.0002"});
    ASSERT_EQ(placed.exitCode, 0) << placed.err.toStdString();
    const QJsonObject w = jsonOf(placed);

    const double us = s["sensitivity_standard_error_pf_per_mn"].toDouble();
    const double uw = w["sensitivity_standard_error_pf_per_mn"].toDouble();
    ASSERT_GT(us, 0.0);
    ASSERT_GT(uw, 0.0);
    const double difference = s["sensitivity_pf_per_mn"].toDouble() - w["sensitivity_pf_per_mn"].toDouble();
    // A sweep reads the beam at its pace: the silicone's creep (1 %, 4 s)
    // follows a 20 s ramp 4 s behind, so the sweep reads up to 1 % × 4/20
    // of the sensitivity below the weights' crept-to-rest value, a bias
    // neither ± holds (docs/calibration.md).
    const double paceBias = 0.01 * 4.0 / 20.0 * w["sensitivity_pf_per_mn"].toDouble();
    EXPECT_LT(difference, 2.0 * std::hypot(us, uw));
    EXPECT_GT(difference, -2.0 * std::hypot(us, uw) - paceBias)
        << "sweep " << s["sensitivity_pf_per_mn"].toDouble() << " ± " << us << ", weights "
        << w["sensitivity_pf_per_mn"].toDouble() << " ± " << uw;
    // One beam: one C0, within the baselines' wander of a minute.
    EXPECT_NEAR(s["c0_pf"].toDouble(), w["c0_pf"].toDouble(), 0.05);
    // The beam lags a sweep: the simulated beam settles with τ = 0.4 s, and
    // its silicone's creep (1 %, 4 s) lengthens the lag found a little.
    // Taken out, loading and unloading are as close as the weights'.
    EXPECT_GE(s["beam_lag_s"].toDouble(), 0.39);
    EXPECT_LE(s["beam_lag_s"].toDouble(), 0.55);
    EXPECT_LT(s["hysteresis_fraction"].toDouble(), 0.01);
    EXPECT_LT(w["hysteresis_fraction"].toDouble(), 0.01);

    // Named, the same channels give the same calibration; a name that is
    // not there is refused.
    const auto named = runCli({"calibrate-capacitive", "--db", db, "--session", session, "--json", "--reference",
                               "load-cell/force", "--capacitance", "beam/capacitance"});
    ASSERT_EQ(named.exitCode, 0) << named.err.toStdString();
    EXPECT_EQ(jsonOf(named)["sensitivity_pf_per_mn"].toDouble(), s["sensitivity_pf_per_mn"].toDouble());
    const auto missing =
        runCli({"calibrate-capacitive", "--db", db, "--session", session, "--reference", "load-cell/torque"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains("no channel 'load-cell/torque'")) << missing.err.toStdString();
}

TEST(ReferenceSweepCli, ASessionWithoutAReferenceForceAndMisusedOptionsAreRefusedWithTheReason)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    QProcess beam;
    ASSERT_TRUE(startEmulator(beam, dir.filePath("beam"), {"--scenario", "capacitive-calibration", "--rate", "100"}));
    const auto recorded = runCli({"record", "--port", dir.filePath("beam"), "--seconds", "3", "--db", db});
    stopEmulator(beam);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();

    const auto alone = runCli({"calibrate-capacitive", "--db", db, "--session", "last"});
    EXPECT_EQ(alone.exitCode, 2);
    EXPECT_TRUE(alone.err.contains("has no reference force")) << alone.err.toStdString();
    const auto noDb = runCli({"calibrate-capacitive", "--session", "last"});
    EXPECT_EQ(noDb.exitCode, 2);
    EXPECT_TRUE(noDb.err.contains("needs both --db and --session")) << noDb.err.toStdString();
    const auto both = runCli({"calibrate-capacitive", "x.csv", "--db", db, "--session", "last"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_TRUE(both.err.contains("either RECORDING.csv or --db")) << both.err.toStdString();
    const auto referenceOfAFile = runCli({"calibrate-capacitive", "x.csv", "--reference", "a/b"});
    EXPECT_EQ(referenceOfAFile.exitCode, 2);
    EXPECT_TRUE(referenceOfAFile.err.contains("a channel of a stored sweep")) << referenceOfAFile.err.toStdString();

    // A sweep needs a rig to push: a panel scan has none.
    QProcess probe;
    EXPECT_FALSE(startEmulator(probe, dir.filePath("p"), {"--scenario", "panel-scan", "--sweep-at", "1"}));
    stopEmulator(probe);
}
