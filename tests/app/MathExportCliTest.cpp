// `sessions export --math`: math channels written beside the stored ones,
// in their declared units, equal to the same arithmetic on the exported
// columns; and the refusals a user meets.
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <cmath>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

namespace {

// A strain in µε and a force in mN at 100 Hz, with a lost row.
QString recording()
{
    QString text = "t [s],a [µε],f [mN]\n";
    QTextStream out(&text);
    for (int i = 0; i < 400; ++i) {
        if (i == 123) continue;
        out << i / 100.0 << ',' << 100.0 * std::sin(i * 0.05) << ',' << 3.0 + std::cos(i * 0.03) << '\n';
    }
    return text;
}

// The recording imported into a store in `dir`; its path.
QString importedRecording(const QTemporaryDir& dir)
{
    const QString csv = dir.filePath("in.csv");
    const QString db = dir.filePath("s.tactiscope");
    writeText(csv, recording());
    EXPECT_EQ(runCli({"import", csv, "--db", db}).exitCode, 0);
    return db;
}

}  // namespace

TEST(MathExportCli, MathChannelsAreTheArithmeticOfTheExportedColumnsInTheirUnits)
{
    QTemporaryDir dir;
    const QString db = importedRecording(dir);
    const QString out = dir.filePath("out.csv");
    const CliResult run =
        runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--output", out, "--math",
                "twice[µN]=2 * f", "--math", "half[µε]=a / 2", "--math", "fa[mN]=f * a + twice"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    QFile file(out);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    EXPECT_EQ(lines.front(), "t [s],a [strain],f [N],twice [µN],half [µε],fa [mN]");
    EXPECT_EQ(lines.size(), 400);  // the header and 399 rows: the lost one has none
    for (int i = 1; i < lines.size(); ++i) {
        const QStringList v = lines[i].split(',');
        ASSERT_EQ(v.size(), 6);
        // The stored channels are binary32, written as the shortest text
        // that reads back to it: the math ran on that binary32 exactly.
        const double a = static_cast<double>(static_cast<float>(v[1].toDouble()));
        const double f = static_cast<double>(static_cast<float>(v[2].toDouble()));
        EXPECT_NEAR(v[3].toDouble(), 2.0 * f * 1e6, 1e-12 * std::abs(2.0 * f * 1e6)) << i;
        EXPECT_NEAR(v[4].toDouble(), a / 2.0 * 1e6, 1e-12 * std::abs(a / 2.0 * 1e6) + 1e-300) << i;
        const double fa = (f * a + 2.0 * f) * 1e3;
        EXPECT_NEAR(v[5].toDouble(), fa, 1e-12 * std::abs(fa)) << i;
    }
    QFile meta(dir.filePath("out.meta.json"));
    ASSERT_TRUE(meta.open(QIODevice::ReadOnly));
    EXPECT_TRUE(meta.readAll().contains("twice[µN]=2 * f")) << "the definitions are kept beside the export";
}

TEST(MathExportCli, AUnitMismatchAndOtherMistakesAreRefusedInWords)
{
    QTemporaryDir dir;
    const QString db = importedRecording(dir);
    const auto refused = [&](const QStringList& more) {
        return runCli(QStringList{"sessions", "--db", db, "export", "last", "--format", "csv", "--output",
                                  dir.filePath("x.csv")} +
                      more);
    };
    const CliResult mixed = refused({"--math", "bad[mN]=f + a"});
    EXPECT_EQ(mixed.exitCode, 2);
    EXPECT_NE(mixed.err.indexOf("not one quantity"), -1) << mixed.err.toStdString();
    EXPECT_NE(mixed.err.indexOf("f [N]"), -1) << mixed.err.toStdString();
    const CliResult wrongUnit = refused({"--math", "k[mm]=f"});
    EXPECT_EQ(wrongUnit.exitCode, 2);
    EXPECT_NE(wrongUnit.err.indexOf("[mm] is in m"), -1) << wrongUnit.err.toStdString();
    EXPECT_EQ(refused({"--math", "nothing"}).exitCode, 2);
    EXPECT_EQ(refused({"--math", "x[1]=q"}).exitCode, 2);
    EXPECT_EQ(runCli({"sessions", "--db", db, "export", "last", "--format", "json", "--output", dir.filePath("x.json"),
                      "--math", "h[µε]=a"})
                  .exitCode,
              2);
    EXPECT_FALSE(QFile::exists(dir.filePath("x.csv")));
}
