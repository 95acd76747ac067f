// `sessions export --derived` on a palpation recorded from the emulator: the
// CSV carries force_high [N], force_low [N], Q and stiffness [N/m] after the
// stored channels; Q is the force ratio while both beams touch and k_o
// follows from it by eq. 2 with the beams' stiffnesses computed here from
// the profile's geometry (k = E·w·t³ / (4·L³)); the stiffness while pressed
// is the specimen's; an import of the export leaves the computed columns
// out, so it reads back as the session recorded; and the report plots the
// forces and Q instead of the counts.
#include "core/report/ReportData.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextFiles.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::testing::readBytes;
using tactiscope::testing::runCli;

namespace {

double beamStiffness(const QJsonObject& beam)
{
    const double E = beam["youngs_modulus_pa"].toDouble(), w = beam["width_m"].toDouble();
    const double t = beam["thickness_m"].toDouble(), L = beam["length_m"].toDouble();
    return E * w * t * t * t / (4.0 * L * L * L);
}

}  // namespace

TEST(DerivedExportCli, APalpationExportsItsForcesQAndStiffnessWithUnits)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("clinic.tactiscope");
    const auto recorded = tactiscope::testing::recordEmulated(dir.path(), db, "palpation", 8);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();

    const QString csv = dir.filePath("derived.csv");
    const auto exported =
        runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--derived", "--output", csv});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    const QStringList lines = QString::fromUtf8(readBytes(csv)).split('\n', Qt::SkipEmptyParts);
    ASSERT_GT(lines.size(), 4000);
    EXPECT_EQ(lines[0], "t [s],high [count],low [count],displacement [m],force_high [N],force_low [N],Q,"
                        "stiffness [N/m]");

    const QJsonObject meta = QJsonDocument::fromJson(readBytes(dir.filePath("derived.meta.json"))).object();
    const QJsonArray computed = meta["computed_columns"].toArray();
    ASSERT_EQ(computed.size(), 4);
    EXPECT_TRUE(computed[0].toObject()["computed_with"].toString().contains("gauge factor"));
    const QJsonObject profile =
        QJsonDocument::fromJson(meta["session"].toObject()["profile_json"].toString().toUtf8()).object();
    const double kHigh = beamStiffness(profile["high"].toObject()), kLow = beamStiffness(profile["low"].toObject());
    ASSERT_GT(kHigh, kLow);

    int pressed = 0;
    double sum = 0.0;
    for (int row = 1; row < lines.size(); ++row) {
        const QStringList f = lines[row].split(',');
        ASSERT_EQ(f.size(), 8) << row;
        const double high = f[4].toDouble(), low = f[5].toDouble(), q = f[6].toDouble(), k = f[7].toDouble();
        if (f[6] == QLatin1String("nan")) {
            EXPECT_FALSE(high > 0.01 && low > 0.01) << row;  // out of contact: no ratio
            continue;
        }
        EXPECT_NEAR(q, high / low, 1e-12 * q) << row;
        if (f[7] == QLatin1String("nan")) continue;                                      // out of the probe's range
        EXPECT_NEAR(k, kHigh * kLow * (q - 1.0) / (kHigh - q * kLow), 1e-9 * k) << row;  // eq. 2
        ++pressed;
        sum += k;
    }
    ASSERT_GT(pressed, 500);
    EXPECT_NEAR(sum / pressed, 117.0, 0.1 * 117.0);  // the scenario's specimen

    // Imported back, the computed columns are not taken for measurements.
    const QString elsewhere = dir.filePath("elsewhere.tactiscope");
    ASSERT_EQ(runCli({"import", csv, "--db", elsewhere}).exitCode, 0);
    core::storage::SessionStore original(db.toStdString(), core::storage::Database::Access::ReadOnly);
    core::storage::SessionStore copy(elsewhere.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto channels = copy.channels(1), recordedChannels = original.channels(1);
    ASSERT_EQ(channels.size(), 3u);
    for (std::size_t c = 0; c < channels.size(); ++c) EXPECT_EQ(channels[c].descriptor, recordedChannels[c].descriptor);
    EXPECT_EQ(copy.zeros(1).size(), original.zeros(1).size());

    // The report's key plot shows the forces and Q in place of the beams'
    // counts, and says what they were computed with.
    const auto report = core::report::gatherReport(original, 1);
    std::vector<std::string> lanes;
    for (const auto& trace : report.traces) lanes.push_back(trace.channel.descriptor.name);
    EXPECT_EQ(lanes, (std::vector<std::string>{"force_high", "force_low", "Q", "displacement"}));
    EXPECT_EQ(report.traces[0].channel.descriptor.unit, "N");
    EXPECT_NE(report.derivedBasis.find("gauge factor"), std::string::npos) << report.derivedBasis;

    // Other modes say what they lack; JSON has no computed columns.
    const auto json = runCli({"sessions", "--db", db, "export", "last", "--format", "json", "--derived", "--output",
                              dir.filePath("x.json")});
    EXPECT_EQ(json.exitCode, 2);
    EXPECT_TRUE(json.err.contains("--derived goes with --format csv")) << json.err.toStdString();
}

TEST(DerivedExportCli, ACapacitiveSessionExportsItsChangeForceAndDeflection)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("lab.tactiscope");
    const auto recorded = tactiscope::testing::recordEmulated(dir.path(), db, "capacitive-weights", 3);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const QString csv = dir.filePath("beam.csv");
    const auto exported =
        runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--derived", "--output", csv});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    const QStringList lines = QString::fromUtf8(readBytes(csv)).split('\n', Qt::SkipEmptyParts);
    ASSERT_GT(lines.size(), 20);
    EXPECT_EQ(lines[0], "t [s],capacitance [F],delta_c [F],relative_change,force [N],deflection [m]");
    // ΔC/C0 is ΔC over the baseline: C − ΔC, as the readout had it.
    for (int row = 1; row < lines.size(); ++row) {
        const QStringList f = lines[row].split(',');
        ASSERT_EQ(f.size(), 6) << row;
        // The stored capacitance is binary32: its shortest text read as a float is exact.
        const double c = static_cast<double>(f[1].toFloat()), delta = f[2].toDouble(), relative = f[3].toDouble();
        EXPECT_NEAR(relative, delta / (c - delta), 1e-9 * std::abs(relative) + 1e-15) << row;
    }
}
