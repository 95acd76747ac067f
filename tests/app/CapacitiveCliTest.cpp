// `tactiscope-cli model` for capacitive_beam and `calibrate-capacitive`.
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <random>

using tactiscope::testing::CliResult;
using tactiscope::testing::jsonOf;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

TEST(CapacitiveCli, ModelOfThePapersSensorNumberOne)
{
    const CliResult run = runCli({"model", TACTISCOPE_SOURCE_DIR "/resources/profiles/capacitive-beam-paper-no1.json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_EQ(o["kind"].toString(), "capacitive_beam");
    EXPECT_NEAR(o["stiffness_n_per_m"].toDouble(), 0.31, 0.01 * 0.31);     // paper: 0.31 N/m
    EXPECT_NEAR(o["compliance_m_per_n"].toDouble(), 3.22, 0.01 * 3.22);    // paper: 3.22 mm/mN
    EXPECT_NEAR(o["force_sensitivity_pf_per_mn"].toDouble(), 1.80, 0.02);  // 1.660 measured + 8.7 %
    EXPECT_NEAR(o["displacement_sensitivity_pf_per_mm"].toDouble(), 0.554, 0.01);
    EXPECT_GT(o["neutral_axis_m"].toDouble(), 0.000939);  // inside the beam, below the sheet
    EXPECT_GT(o["sheet_strain_per_newton"].toDouble(), 0.0);
}

TEST(CapacitiveCli, CalibrationFromForceAndCapacitanceRows)
{
    // 50 baseline rows (σ = 0.004 pF) and 15 weights of 10 mgf steps on a
    // 1.660 pF/mN sensor, each with the same noise.
    QTemporaryDir dir;
    std::mt19937 random(8);
    std::normal_distribution<double> noise(0.0, 0.004);
    QString text = "force_n,capacitance_pf\n";
    QTextStream out(&text);
    for (int i = 0; i < 50; ++i) out << "0," << QString::number(51.44 + noise(random), 'g', 12) << '\n';
    for (int mgf = 10; mgf <= 150; mgf += 10) {
        const double force = mgf * 9.80665e-6;
        out << QString::number(force, 'g', 12) << ','
            << QString::number(51.44 + 1.660e3 * force + noise(random), 'g', 12) << '\n';
    }
    writeText(dir.filePath("weights.csv"), text);
    const CliResult run =
        runCli({"calibrate-capacitive", dir.filePath("weights.csv"), "--json", "--contact-area-mm2", "9"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_NEAR(o["c0_pf"].toDouble(), 51.44, 0.002);
    EXPECT_NEAR(o["baseline_sigma_pf"].toDouble(), 0.004, 0.0015);
    EXPECT_NEAR(o["sensitivity_pf_per_mn"].toDouble(), 1.660, 0.02);
    EXPECT_NEAR(o["intercept_pf"].toDouble(), 0.0, 0.005);
    EXPECT_GE(o["r_squared"].toDouble(), 0.999);
    // 3σ / sensitivity: about 0.012/1.66 mN = 7 µN.
    EXPECT_NEAR(o["detection_limit_mn"].toDouble(), 3 * o["baseline_sigma_pf"].toDouble() / 1.66, 0.001);
    EXPECT_NEAR(o["pressure_sensitivity_per_kpa"].toDouble(), 0.290, 0.005);
}

TEST(CapacitiveCli, BadReadingsExitWithCodeTwo)
{
    QTemporaryDir dir;
    writeText(dir.filePath("nobase.csv"), "force_n,capacitance_pf\n0.001,52\n0.002,53\n");
    writeText(dir.filePath("negative.csv"), "force_n,capacitance_pf\n0,51\n0,51\n-0.001,52\n");
    writeText(dir.filePath("falling.csv"), "force_n,capacitance_pf\n0,51\n0,51\n0.001,50\n0.002,49\n");
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"calibrate-capacitive", dir.filePath("missing.csv")}, "cannot open"},
        {{"calibrate-capacitive", dir.filePath("nobase.csv")}, "at least two rows with force 0"},
        {{"calibrate-capacitive", dir.filePath("negative.csv")}, "line 4: force must not be negative"},
        {{"calibrate-capacitive", dir.filePath("falling.csv")}, "does not rise with force"},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(run.err.section('\n', 0, 0).contains(message)) << run.err.toStdString();
    }
}

namespace {

// The simulator's cumulative protocol: the unloaded baseline, 10 … 150 mgf
// stacked in 10 mgf steps, taken off again, and the baseline at the end.
QString simulatorLoads()
{
    QStringList loads{"0"};
    for (int mgf = 10; mgf <= 150; mgf += 10) loads << QString::number(mgf);
    for (int mgf = 140; mgf >= 0; mgf -= 10) loads << QString::number(mgf);
    return loads.join(',');
}

}  // namespace

TEST(CapacitiveCli, TheSimulatorsRawRecordingCalibratesItsBeamAndItsDriftIsNotHysteresis)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("c.csv");
    ASSERT_EQ(runCli({"simulate", "--scenario", "capacitive-weights", "--seconds", "252", "--output", csv}).exitCode,
              0);
    const CliResult model =
        runCli({"model", TACTISCOPE_SOURCE_DIR "/resources/profiles/capacitive-beam-paper-no1.json"});
    const double beam_pf_per_mn = jsonOf(model)["force_sensitivity_pf_per_mn"].toDouble();
    ASSERT_GT(beam_pf_per_mn, 1.0);

    const CliResult run = runCli({"calibrate-capacitive", csv, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    // The simulator's beam, plus its 1 % creep.
    EXPECT_NEAR(o["sensitivity_pf_per_mn"].toDouble(), beam_pf_per_mn, 0.03 * beam_pf_per_mn);
    // σ of the first baseline alone: the simulator's 0.004 pF of noise, not
    // the drift between the two baselines (0.0005 pF/s over 242 s).
    EXPECT_NEAR(o["baseline_sigma_pf"].toDouble(), 0.004, 0.001);
    EXPECT_LT(o["detection_limit_mgf"].toDouble(), 2.0);
    EXPECT_NEAR(o["detection_limit_mn"].toDouble(),
                3.0 * o["baseline_sigma_pf"].toDouble() / o["sensitivity_pf_per_mn"].toDouble(), 1e-12);
    EXPECT_NEAR(o["drift_pf_per_s"].toDouble(), 0.0005, 0.0002);
    EXPECT_LT(o["hysteresis_fraction"].toDouble(), 0.01) << "the drift and the creep are not hysteresis";
    EXPECT_EQ(o["steps"].toArray().size(), 29);
    int unloading = 0;
    for (const auto step : o["steps"].toArray()) unloading += step.toObject()["loading"].toBool() ? 0 : 1;
    EXPECT_EQ(unloading, 14);

    // The same capacitance without the load column, the loads given in
    // order: the steps found by their stability give the same calibration.
    QFile full(csv), bare(dir.filePath("bare.csv"));
    ASSERT_TRUE(full.open(QIODevice::ReadOnly) && bare.open(QIODevice::WriteOnly));
    while (!full.atEnd()) {
        const QByteArray line = full.readLine();
        bare.write(line.left(line.lastIndexOf(',')) + '\n');
    }
    bare.close();
    const CliResult byOrder =
        runCli({"calibrate-capacitive", bare.fileName(), "--json", "--loads-mgf", simulatorLoads()});
    ASSERT_EQ(byOrder.exitCode, 0) << byOrder.err.toStdString();
    EXPECT_NEAR(jsonOf(byOrder)["sensitivity_pf_per_mn"].toDouble(), o["sensitivity_pf_per_mn"].toDouble(),
                0.002 * o["sensitivity_pf_per_mn"].toDouble());
    EXPECT_NEAR(jsonOf(byOrder)["c0_pf"].toDouble(), o["c0_pf"].toDouble(), 0.001);

    const CliResult noLoads = runCli({"calibrate-capacitive", bare.fileName()});
    EXPECT_EQ(noLoads.exitCode, 2);
    EXPECT_TRUE(noLoads.err.contains("has no load column: give the loads placed")) << noLoads.err.toStdString();
    const CliResult tooFew = runCli({"calibrate-capacitive", bare.fileName(), "--loads-mgf", "0,10,20"});
    EXPECT_EQ(tooFew.exitCode, 2);
    EXPECT_TRUE(tooFew.err.contains("stable steps, but 3 loads are listed")) << tooFew.err.toStdString();
}

TEST(CapacitiveCli, PerSampleRowsCountEveryRowOfAnUnloadingStepAndKeepTheFinalBaselineOutOfC0)
{
    // Three rows per step: 0, 10, 20, 10, 0 (mgf ×1000), exact on a line of
    // 2 pF per mN, with the final baseline 0.05 pF higher (drift). Before,
    // only the first row of the unloading step counted as unloading and the
    // final baseline was pooled into C0 and its σ.
    QTemporaryDir dir;
    QString text = "force_n,capacitance_pf\n";
    for (const auto& [force, pf] : std::vector<std::pair<double, double>>{{0, 50.0},
                                                                          {0, 50.002},
                                                                          {0, 49.998},
                                                                          {0.1, 50.2},
                                                                          {0.1, 50.2},
                                                                          {0.1, 50.2},
                                                                          {0.2, 50.4},
                                                                          {0.2, 50.4},
                                                                          {0.2, 50.4},
                                                                          {0.1, 50.2},
                                                                          {0.1, 50.2},
                                                                          {0.1, 50.2},
                                                                          {0, 50.05},
                                                                          {0, 50.05}})
        text += QString::number(force) + ',' + QString::number(pf, 'g', 10) + '\n';
    writeText(dir.filePath("rows.csv"), text);
    const CliResult run = runCli({"calibrate-capacitive", dir.filePath("rows.csv"), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_NEAR(o["c0_pf"].toDouble(), 50.0, 1e-9);
    EXPECT_NEAR(o["baseline_sigma_pf"].toDouble(), 0.002, 1e-9);  // of 50, 50.002, 49.998
    EXPECT_NEAR(o["final_baseline_shift_pf"].toDouble(), 0.05, 1e-9);
    const QJsonArray steps = o["steps"].toArray();
    ASSERT_EQ(steps.size(), 3);
    EXPECT_TRUE(steps[0].toObject()["loading"].toBool());
    EXPECT_TRUE(steps[1].toObject()["loading"].toBool());
    EXPECT_FALSE(steps[2].toObject()["loading"].toBool());
    EXPECT_EQ(steps[2].toObject()["samples"].toInt(), 3);
    EXPECT_NEAR(o["hysteresis_fraction"].toDouble(), 0.0, 1e-9);  // 10 mgf up and down alike
    EXPECT_NEAR(o["sensitivity_pf_per_mn"].toDouble(), 2e-3, 1e-9);
}
