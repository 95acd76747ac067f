// `compliance` on simulated phantoms across and beyond the probe's range
// (`simulate --scenario palpation --object-stiffness K --depths-mm …`):
// every press either reads the phantom's true stiffness within 2u or says
// why it has no number — clipped at a beam's ADC limit, or below/above the
// probe's range with the bound — and the session reading does the same,
// with the probe's usable range and whether its presses agree.
#include "support/CliRunner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

namespace {

const QString kProbe = QStringLiteral(TACTISCOPE_SOURCE_DIR "/resources/profiles/compliance-probe-paper.json");

QJsonObject complianceOf(const QString& folder, double stiffness, const QString& depths, int seed)
{
    const QString csv = folder + QStringLiteral("/k%1-s%2.csv").arg(stiffness).arg(seed);
    const CliResult simulated =
        runCli({"simulate", "--scenario", "palpation", "--object-stiffness", QString::number(stiffness), "--depths-mm",
                depths, "--seconds", "20", "--seed", QString::number(seed), "--output", csv});
    EXPECT_EQ(simulated.exitCode, 0) << simulated.err.toStdString();
    const CliResult run = runCli({"compliance", kProbe, csv, "--json"});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

// A reading's number covers the truth within 2u, or it has a reason.
void expectTrueOrFlagged(const QJsonObject& reading, double truth, const std::string& what)
{
    const QString status = reading["status"].toString();
    if (status == QLatin1String("ok")) {
        const double k = reading["object_stiffness_n_per_m"].toDouble();
        const double u = reading["uncertainty_n_per_m"].toDouble();
        EXPECT_LE(std::abs(k - truth), 2.0 * u) << what << ": " << k << " ± " << u << " for " << truth;
        return;
    }
    ASSERT_TRUE(status == QLatin1String("clipped") || status == QLatin1String("below-range") ||
                status == QLatin1String("above-range"))
        << what << ": status '" << status.toStdString() << "'";
    EXPECT_FALSE(reading.contains("object_stiffness_n_per_m")) << what << ": a flagged reading has no number";
    if (status == QLatin1String("below-range") && reading.contains("bound_n_per_m")) {
        EXPECT_GT(reading["bound_n_per_m"].toDouble(), truth) << what << ": the bound it is below";
    }
    if (status == QLatin1String("above-range") && reading.contains("bound_n_per_m")) {
        EXPECT_LT(reading["bound_n_per_m"].toDouble(), truth) << what << ": the bound it is above";
    }
}

}  // namespace

TEST(ComplianceRangeCli, EveryReadingIsTrueOrFlaggedAcrossTheProbesRange)
{
    QTemporaryDir dir;
    std::optional<QJsonArray> probesRange;
    for (const double truth : {2.0, 5.0, 117.0, 5000.0, 100000.0}) {
        const QJsonObject o = complianceOf(dir.path(), truth, QStringLiteral("2,4,6,8"), 3);
        const std::string what = std::to_string(truth) + " N/m";
        ASSERT_TRUE(o.contains("status")) << what;
        const QJsonArray presses = o["presses"].toArray();
        ASSERT_GE(presses.size(), 2) << what;  // 2 N/m: the 2 mm presses stay below the contact threshold
        for (const auto press : presses) expectTrueOrFlagged(press.toObject(), truth, what + ", a press");
        expectTrueOrFlagged(o, truth, what + ", the session");
        const QJsonArray range = o["usable_range_n_per_m"].toArray();
        ASSERT_EQ(range.size(), 2) << what;
        EXPECT_LT(range[0].toDouble(), 117.0);
        EXPECT_GT(range[1].toDouble(), 117.0);
        // The probe's, from its beams and converters: one range whatever was pressed
        // (it was the presses' before, 0.018 to 5.3·10⁶ N/m for 117 N/m).
        if (!probesRange) probesRange = range;
        EXPECT_EQ(range, *probesRange) << what;
        EXPECT_TRUE(o.contains("consistency")) << what;
    }
}

// The stiff beam's ADC clips on deep presses of a stiff object: those are
// flagged and left out of the session reading, which the shallow ones make.
TEST(ComplianceRangeCli, DeepPressesOfAStiffObjectAreClippedAndLeftOut)
{
    QTemporaryDir dir;
    const QJsonObject o = complianceOf(dir.path(), 5000.0, QStringLiteral("2,8"), 5);
    int clipped = 0, read = 0;
    for (const auto press : o["presses"].toArray()) {
        const QJsonObject p = press.toObject();
        if (p["status"].toString() == QLatin1String("clipped")) {
            ++clipped;
            EXPECT_GT(p["samples_at_limit"].toObject()["high"].toInt(), 0) << "the stiff beam is the one at its limit";
        } else if (p["status"].toString() == QLatin1String("ok")) {
            ++read;
        }
    }
    EXPECT_GE(clipped, 1);
    EXPECT_EQ(o["presses_read"].toInt(), read);
    EXPECT_EQ(o["presses_clipped"].toInt(), clipped);
}
