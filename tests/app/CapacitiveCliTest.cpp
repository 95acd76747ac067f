// `tactiscope-cli model` for capacitive_beam and `calibrate-capacitive`.
#include "support/CliRunner.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <random>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

namespace {

QJsonObject json(const CliResult& run)
{
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

void write(const QString& path, const QString& text)
{
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text.toUtf8());
}

}  // namespace

TEST(CapacitiveCli, ModelOfThePapersSensorNumberOne)
{
    const CliResult run = runCli({"model", TACTISCOPE_SOURCE_DIR "/resources/profiles/capacitive-beam-paper-no1.json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = json(run);
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
    write(dir.filePath("weights.csv"), text);
    const CliResult run =
        runCli({"calibrate-capacitive", dir.filePath("weights.csv"), "--json", "--contact-area-mm2", "9"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = json(run);
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
    write(dir.filePath("nobase.csv"), "force_n,capacitance_pf\n0.001,52\n0.002,53\n");
    write(dir.filePath("negative.csv"), "force_n,capacitance_pf\n0,51\n0,51\n-0.001,52\n");
    write(dir.filePath("falling.csv"), "force_n,capacitance_pf\n0,51\n0,51\n0.001,50\n0.002,49\n");
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
