// `tactiscope-cli compliance` on what probes and the simulator record: the
// simulator's raw counts read within 1 % of the specimen it simulates, with
// an uncertainty that is never printed as zero; a recorded session's export
// reads exactly as the recording read it live; the paper's step procedure;
// and recordings it must refuse.
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tactiscope;
using tactiscope::testing::CliResult;
using tactiscope::testing::jsonOf;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

namespace {

const QString kProbe = QStringLiteral(TACTISCOPE_SOURCE_DIR "/resources/profiles/compliance-probe-paper.json");
constexpr double kSimulatedSpecimen_n_per_m = 117.0;  // PalpationParameters' default

}  // namespace

TEST(ComplianceRecordingCli, TheSimulatorsCountsReadTheSimulatedSpecimenWithinOnePercent)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("p.csv");
    ASSERT_EQ(runCli({"simulate", "--scenario", "palpation", "--seconds", "20", "--output", csv}).exitCode, 0);
    const CliResult run = runCli({"compliance", kProbe, csv, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    const double k = o["object_stiffness_n_per_m"].toDouble();
    EXPECT_NEAR(k, kSimulatedSpecimen_n_per_m, 0.01 * kSimulatedSpecimen_n_per_m);
    EXPECT_GE(o["presses_read"].toInt(), 5);
    EXPECT_EQ(o["zero"].toString(), "first_half_second");
    // Each part of the uncertainty, and the whole from them.
    const double noise = o["standard_error_n_per_m"].toDouble(), zero = o["zero_uncertainty_n_per_m"].toDouble();
    EXPECT_GT(noise, 0.0);
    EXPECT_GT(zero, 0.0);
    EXPECT_NEAR(o["uncertainty_n_per_m"].toDouble(), std::hypot(noise, zero), 1e-12);
    EXPECT_LE(std::abs(k - kSimulatedSpecimen_n_per_m), 3.0 * o["uncertainty_n_per_m"].toDouble());
    for (const auto press : o["presses"].toArray()) {
        const QJsonObject p = press.toObject();
        EXPECT_NEAR(p["q"].toDouble(), 1620.0 * (117.0 + 60.0) / (60.0 * (117.0 + 1620.0)), 2e-3);  // eq. 1
        EXPECT_TRUE(p.contains("displacement_slope_standard_error_n_per_m_per_m"));
    }

    const CliResult text = runCli({"compliance", kProbe, csv});
    ASSERT_EQ(text.exitCode, 0) << text.err.toStdString();
    EXPECT_TRUE(text.out.startsWith("object stiffness: ")) << text.out.toStdString();
    // An uncertainty printed as zero ("± 0", "± 0.0", "± 0.00 …") never.
    EXPECT_FALSE(text.out.contains(QRegularExpression(QStringLiteral("± 0(\\.0*)?(?![0-9.])"))))
        << text.out.toStdString();
    EXPECT_TRUE(text.out.contains("standard uncertainty: noise ")) << text.out.toStdString();
}

TEST(ComplianceRecordingCli, ARecordedSessionsExportReadsAsTheRecordingReadItLive)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("clinic.tactiscope");
    const auto recorded = tactiscope::testing::recordEmulated(dir.path(), db, "palpation", 8);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const QString csv = dir.filePath("session.csv");
    const CliResult exported = runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--output", csv});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();

    const CliResult run = runCli({"compliance", kProbe, csv, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_EQ(o["zero"].toString(), "recorded");
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto readings = store.readings(1);
    ASSERT_GE(readings.size(), 2u);
    std::vector<QJsonObject> inRange;
    for (const auto press : o["presses"].toArray())
        if (press.toObject().contains("object_stiffness_n_per_m")) inRange.push_back(press.toObject());
    ASSERT_EQ(inRange.size(), readings.size());
    for (std::size_t i = 0; i < readings.size(); ++i) {
        EXPECT_NEAR(inRange[i]["object_stiffness_n_per_m"].toDouble(), readings[i].value, 1e-9 * readings[i].value);
        ASSERT_TRUE(readings[i].standardError);
        EXPECT_NEAR(inRange[i]["uncertainty_n_per_m"].toDouble(), *readings[i].standardError,
                    1e-9 * *readings[i].standardError);
        EXPECT_NEAR(inRange[i]["start_s"].toDouble(), readings[i].start_s, 1e-9);
    }
}

TEST(ComplianceRecordingCli, TheStepProcedureReadsAThousandReadingsPerStepAndRejectsOnce)
{
    // Held at 1, 2 and 3 mm for 1200 readings each and at 4 mm for 500,
    // on a 174 N/m object: F = x·k·k_o/(k + k_o) with k_h = 1620, k_l = 60
    // N/m by hand, σ = 2 mN on each force and one 1 N spike per step.
    QTemporaryDir dir;
    std::mt19937 random(4);
    std::normal_distribution<double> noise(0.0, 0.002);
    QString text = "displacement_m,force_high_n,force_low_n\n";
    QTextStream out(&text);
    for (const auto& [mm, count] : {std::pair{1, 1200}, {2, 1200}, {3, 1200}, {4, 500}}) {
        const double x = mm * 1e-3;
        for (int i = 0; i < count; ++i) {
            const double high = x * 1620.0 * 174.0 / 1794.0 + noise(random) + (i == 100 ? 1.0 : 0.0);
            const double low = x * 60.0 * 174.0 / 234.0 + noise(random);
            out << QString::number(x, 'g', 17) << ',' << QString::number(high, 'g', 17) << ','
                << QString::number(low, 'g', 17) << '\n';
        }
    }
    writeText(dir.filePath("steps.csv"), text);
    const CliResult run = runCli({"compliance", kProbe, dir.filePath("steps.csv"), "--steps", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_EQ(o["procedure"].toString(), "steps");
    EXPECT_EQ(o["steps_in_range"].toInt(), 3);
    const QJsonArray steps = o["steps"].toArray();
    ASSERT_EQ(steps.size(), 4);
    for (int s = 0; s < 3; ++s) {
        const QJsonObject step = steps[s].toObject();
        EXPECT_NEAR(step["displacement_m"].toDouble(), (s + 1) * 1e-3, 1e-12);
        EXPECT_EQ(step["readings_available"].toInt(), 1200);
        EXPECT_GE(step["rejected_high"].toInt(), 1) << "the spike";
        // The mean of 1000 readings with σ = 2 mN on F_L ≈ 44.6 mN·mm: Q to
        // about 0.03 %, k_o to a few tenths of a per cent at 1 mm.
        EXPECT_NEAR(step["object_stiffness_n_per_m"].toDouble(), 174.0, 0.01 * 174.0);
    }
    EXPECT_TRUE(steps[3].toObject()["short"].toBool());
    EXPECT_EQ(steps[3].toObject()["readings_available"].toInt(), 500);
    EXPECT_NEAR(o["object_stiffness_n_per_m"].toDouble(), 174.0, 0.005 * 174.0);
    EXPECT_GT(o["standard_error_n_per_m"].toDouble(), 0.0);
}

TEST(ComplianceRecordingCli, RecordingsItCannotReadAreRefusedWithTheReason)
{
    QTemporaryDir dir;
    writeText(dir.filePath("unitless.csv"), "t,high,low,displacement [m]\n0,1,2,0\n0.001,1,2,0\n");
    writeText(dir.filePath("short.csv"), "t [s],high [count],low [count],displacement [m]\n0,1,2,0\n0.001,1,2,0\n");
    writeText(dir.filePath("other-probe.json"),
              R"({"kind": "gauge_factor", "sensor": "another probe — stiff beam", "operator": "x",
              "timestamp_utc": "2026-11-20T10:00:00Z", "values": {"gauge_factor": 2.1},
              "fit": {"slope": 1, "intercept": 0, "r_squared": 1, "slope_standard_error": 0,
                      "intercept_standard_error": 0, "residual_standard_deviation": 0, "points": 5,
                      "residuals": []}})");
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"compliance", kProbe, dir.filePath("unitless.csv")}, "the beam column 'high' has no unit"},
        {{"compliance", kProbe, dir.filePath("short.csv")}, "shorter than the first zero"},
        {{"compliance", kProbe, dir.filePath("short.csv"), "--calibration", dir.filePath("other-probe.json")},
         "has no gauge_factor record for"},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(run.err.section('\n', 0, 0).contains(message)) << run.err.toStdString();
    }
}
