// `tactiscope-cli model` and `tactiscope-cli compliance` as other tools use
// them: profiles and readings written by the test, JSON checked against
// hand-computed values.
#include "support/CliRunner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

namespace {

const char* kPairProfile = R"({"kind": "compliance_pair", "name": "paper probe",
    "high": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.003, "youngs_modulus_pa": 3e9},
    "low": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.001, "youngs_modulus_pa": 3e9}})";
const char* kSpecimenProfile = R"({"kind": "cantilever", "name": "specimen", "length_m": 0.07, "width_m": 0.01,
    "thickness_m": 0.002, "youngs_modulus_pa": 3e9})";

class ComplianceCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_dir.isValid());
        write("pair.json", kPairProfile);
        write("specimen.json", kSpecimenProfile);
    }
    QString path(const char* name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    void write(const char* name, const QString& text) const
    {
        QFile file(path(name));
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(text.toUtf8());
    }
    static QJsonObject json(const CliResult& run) { return QJsonDocument::fromJson(run.out.toUtf8()).object(); }

    QTemporaryDir m_dir;
};

// A press into a 174 N/m object: k_h = 1620, k_l = 60 N/m by hand, forces
// F = x·k·k_o/(k + k_o); a lifted start (zeros) and two spikes on the way.
QString pressReadings(double k_o)
{
    QString text = "displacement_m,force_high_n,force_low_n\n";
    QTextStream out(&text);
    for (int i = 0; i < 20; ++i) out << -0.001 << ",0,0\n";
    for (int i = 1; i <= 400; ++i) {
        const double x = i * 2e-5;
        double fh = x * 1620.0 * k_o / (1620.0 + k_o);
        const double fl = x * 60.0 * k_o / (60.0 + k_o);
        if (i == 150 || i == 300) fh *= 1.5;  // spikes the 3σ rule must reject
        out << QString::number(x, 'g', 17) << ',' << QString::number(fh, 'g', 17) << ',' << QString::number(fl, 'g', 17)
            << '\n';
    }
    return text;
}

}  // namespace

TEST_F(ComplianceCli, ModelOfACantilever)
{
    const CliResult run = runCli({"model", path("specimen.json")});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = json(run);
    EXPECT_NEAR(o["stiffness_n_per_m"].toDouble(), 0.06 / (0.07 * 0.07 * 0.07), 1e-9);  // 174.9 N/m
    EXPECT_NEAR(o["strain_per_newton"].toDouble(), 6 * 0.07 / (3e9 * 0.01 * 4e-6), 1e-12);
    EXPECT_NEAR(o["deflection_m_per_newton"].toDouble(), 0.07 * 0.07 * 0.07 / 0.06, 1e-12);
}

TEST_F(ComplianceCli, ModelOfTheCompliancePairWithQAndObjectStiffness)
{
    CliResult run = runCli({"model", path("pair.json"), "--q", "2.7512953367875648", "--object-stiffness", "117"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    QJsonObject o = json(run);
    EXPECT_NEAR(o["k_high_n_per_m"].toDouble(), 1620.0, 1e-9);
    EXPECT_NEAR(o["k_low_n_per_m"].toDouble(), 60.0, 1e-9);
    EXPECT_NEAR(o["q_max"].toDouble(), 27.0, 1e-12);
    EXPECT_NEAR(o["object_stiffness_n_per_m"].toDouble(), 117.0, 1e-9);  // Q(117) = 1620·177/(60·1737)
    EXPECT_NEAR(o["q"].toDouble(), 1620.0 * 177.0 / (60.0 * 1737.0), 1e-12);
    EXPECT_NEAR(o["dq_dk_m_per_n"].toDouble(), 1620.0 * 1560.0 / (60.0 * 1737.0 * 1737.0), 1e-12);

    run = runCli({"model", path("pair.json"), "--q", "0.8"});
    EXPECT_EQ(json(run)["range"].toString(), "below");
    EXPECT_FALSE(json(run).contains("object_stiffness_n_per_m"));
    EXPECT_EQ(json(runCli({"model", path("pair.json"), "--q", "27.5"}))["range"].toString(), "above");
    // k_h/k_l computes as 27.000000000000004: Q = 27 is the end of the
    // range, not an object of 10¹⁹ N/m.
    run = runCli({"model", path("pair.json"), "--q", "27"});
    EXPECT_EQ(json(run)["range"].toString(), "above") << run.out.toStdString();
    EXPECT_FALSE(json(run).contains("object_stiffness_n_per_m"));
}

TEST_F(ComplianceCli, ComplianceReadsThePressRejectsSpikesAndSkipsNoContact)
{
    write("press.csv", pressReadings(174.0));
    const CliResult run = runCli({"compliance", path("pair.json"), path("press.csv"), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = json(run);
    EXPECT_NEAR(o["object_stiffness_n_per_m"].toDouble(), 174.0, 1e-6);
    EXPECT_EQ(o["rows_rejected"].toInt(), 2);
    EXPECT_EQ(o["rows_used"].toInt() + o["rows_rejected"].toInt() + o["rows_skipped"].toInt(), 420);
    EXPECT_GE(o["rows_skipped"].toInt(), 20);
    EXPECT_NEAR(o["displacement_slope_n_per_m_per_m"].toDouble(), 0.0, 1.0);
    EXPECT_LT(o["standard_error_n_per_m"].toDouble(), 1e-6);
    // Exact forces: said in words, not as "± 0.0".
    const CliResult text = runCli({"compliance", path("pair.json"), path("press.csv")});
    EXPECT_TRUE(text.out.startsWith("object stiffness: 174 N/m (no scatter)")) << text.out.toStdString();
}

TEST_F(ComplianceCli, PlacesTheReadingAgainstReferenceTissues)
{
    write("press.csv", pressReadings(127.0));
    const CliResult run = runCli({"compliance", path("pair.json"), path("press.csv"), "--json", "--tissues",
                                  TACTISCOPE_SOURCE_DIR "/resources/reference-tissues.json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonArray nearest = json(run)["nearest_tissues"].toArray();
    ASSERT_EQ(nearest.size(), 3);
    EXPECT_TRUE(nearest[0].toObject()["name"].toString().startsWith("Liver (pig"));
    EXPECT_NEAR(nearest[0].toObject()["distance_n_per_m"].toDouble(), 0.0, 1e-6);
}

TEST_F(ComplianceCli, TooStiffAnObjectIsReportedAsAboveRange)
{
    write("stiff.csv", "displacement_m,force_high_n,force_low_n\n0.001,3.0,0.1\n0.002,6.0,0.2\n0.003,9.0,0.3\n");
    const CliResult run = runCli({"compliance", path("pair.json"), path("stiff.csv"), "--json"});
    ASSERT_EQ(run.exitCode, 0);
    EXPECT_EQ(json(run)["range"].toString(), "above");  // Q = 30 > 27
}

TEST_F(ComplianceCli, BadProfilesAndReadingsExitWithCodeTwo)
{
    write("broken.json", R"({"kind": "cantilever", "name": "x", "length_m": 0.05})");
    write("nocolumn.csv", "displacement_m,force_high_n\n0.001,1\n");
    write("nocontact.csv", "displacement_m,force_high_n,force_low_n\n0.001,0.001,0.001\n");
    write("press.csv", pressReadings(60.0));
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"model", path("broken.json")}, "broken.json: width_m: missing"},
        {{"model", path("missing.json")}, "cannot open"},
        {{"model", path("specimen.json"), "--q", "2"}, "apply to compliance_pair"},
        {{"model", path("pair.json"), "--object-stiffness", "-5"}, "--object-stiffness"},
        {{"compliance", path("specimen.json"), path("press.csv")}, "a compliance_pair profile is needed"},
        {{"compliance", path("pair.json"), path("nocolumn.csv")}, "no column 'force_low_n'"},
        {{"compliance", path("pair.json"), path("nocontact.csv")}, "no row has both forces above"},
        {{"compliance", path("pair.json")}, "needs PROFILE.json and RECORDING.csv"},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        const QString first = run.err.section('\n', 0, 0);
        EXPECT_TRUE(first.startsWith("tactiscope-cli: ") && first.contains(message))
            << first.toStdString() << " lacks " << message.toStdString();
    }
}

TEST_F(ComplianceCli, ANumberBeyondADoubleIsAnErrorNamingItsKeyNotAnAbort)
{
    // Before, nlohmann's overflow error escaped: `model` and `compliance`
    // died of an uncaught exception (issue 19).
    QString pair = kPairProfile;
    pair.replace(QStringLiteral("\"length_m\": 0.05, \"width_m\": 0.01, \"thickness_m\": 0.003"),
                 QStringLiteral("\"length_m\": 1e400, \"width_m\": 0.01, \"thickness_m\": 0.003"));
    write("overflow.json", pair);
    const CliResult model = runCli({"model", path("overflow.json")});
    EXPECT_EQ(model.exitCode, 2);
    EXPECT_TRUE(model.err.contains(QStringLiteral("overflow.json: high.length_m: number overflow parsing '1e400'")))
        << model.err.toStdString();

    write("press.csv", pressReadings(127.0));
    write("tissues.json", R"({"tissues": [{"name": "a", "stiffness_n_per_m": 40}, {"name": "b",
        "stiffness_n_per_m": 4e400}]})");
    const CliResult compliance =
        runCli({"compliance", path("pair.json"), path("press.csv"), "--tissues", path("tissues.json")});
    EXPECT_EQ(compliance.exitCode, 2);
    EXPECT_TRUE(compliance.err.contains(QStringLiteral("tissues[1].stiffness_n_per_m: number overflow")))
        << compliance.err.toStdString();
}
