// A maker's board (the text protocol: no kinds, no mode) through the real
// serial path: `record` stores it in the general mode without --mode, and
// `sessions show`, `export` and `report` read it with its channels' names;
// given roles, the same device records a panel scan with the detector's
// events; roles that are wrong are refused before anything is recorded.
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

// The emulated panel probe printing Serial-Plotter lines "a:… b:…".
tactiscope::testing::CliResult recordText(const QString& dir, const QString& db, const QStringList& extra)
{
    const QString link = dir + QStringLiteral("/probe");
    QProcess emulator;
    if (!startEmulator(emulator, link,
                       {"--protocol", "text", "--scenario", "panel-scan", "--rate", "500", "--seed", "5"}))
        return {-1, {}, QStringLiteral("the emulator did not start")};
    auto result = runCli(
        QStringList{"record", "--port", link, "--protocol", "text", "--rate", "500", "--seconds", "8", "--db", db} +
        extra);
    stopEmulator(emulator);
    return result;
}

}  // namespace

TEST(GeneralModeCli, ATextDeviceRecordsInGeneralModeAndEveryReaderWorksOnIt)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("maker.tactiscope");
    const auto result = recordText(dir.path(), db, {"--subject", "board-1"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_GT(sessionIdIn(result.out), 0) << result.out.toStdString();
    EXPECT_TRUE(result.out.contains(QStringLiteral("general: 2 channels as they came, no analysis")))
        << result.out.toStdString();

    const auto show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject json = QJsonDocument::fromJson(show.out.toUtf8()).object();
    EXPECT_EQ(json["session"].toObject()["mode"].toString(), "general") << show.out.toStdString();
    EXPECT_EQ(json["session"].toObject()["verdict"].toString(), "");
    EXPECT_TRUE(json["events"].toArray().isEmpty());

    const QString csv = dir.filePath("board-1.csv");
    const auto exported = runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--output", csv});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString header = QString::fromUtf8(file.readLine()).trimmed();
    EXPECT_TRUE(header.contains(QStringLiteral("a")) && header.contains(QStringLiteral("b"))) << header.toStdString();
    int rows = 0;
    while (!file.atEnd()) rows += file.readLine().isEmpty() ? 0 : 1;
    EXPECT_GT(rows, 3500);  // 8 s at 500 Hz, less the start

    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    const QString pdf = dir.filePath("board-1.pdf");
    const auto report = runCli({"report", "--db", db, "--session", "last", "--output", pdf});
    ASSERT_EQ(report.exitCode, 0) << report.err.toStdString();
    const QString text = pdfText(pdf);
    EXPECT_TRUE(text.simplified().contains(QStringLiteral("Mode general"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("board-1"))) << text.toStdString();
}

TEST(GeneralModeCli, GivenRolesAndItsUnitsTheSameTextDeviceRecordsAPanelScan)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("line3.tactiscope");
    const auto result = recordText(
        dir.path(), db,
        {"--roles", "a=cantilever-a,b=cantilever-b", "--units", "a=strain,b=strain", "--mode", "panel-scan"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject json = QJsonDocument::fromJson(show.out.toUtf8()).object();
    EXPECT_EQ(json["session"].toObject()["mode"].toString(), "panel-scan");
    EXPECT_EQ(json["session"].toObject()["verdict"].toString(), "defects found");
    // 8 s of 2 s strokes over one dent: 8 crossings, one maybe cut by the ends.
    const QJsonArray events = json["events"].toArray();
    EXPECT_GE(events.size(), 7) << show.out.toStdString();
    EXPECT_LE(events.size(), 9);
    for (const auto& event : events) EXPECT_EQ(event.toObject()["kind"].toString(), "defect");
    // The roles are part of the record.
    const auto text = runCli({"sessions", "--db", db, "show", "last"});
    EXPECT_TRUE(text.out.contains(QStringLiteral("a [strain] as cantilever-a, b [strain] as cantilever-b")))
        << text.out.toStdString();
}

TEST(GeneralModeCli, WrongRolesAndAModeWithoutThemAreRefusedWithWhatToDo)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const auto badRole = runCli({"record", "--port", dir.filePath("none"), "--db", db, "--roles", "a=cantilever-z"});
    EXPECT_EQ(badRole.exitCode, 2);
    EXPECT_TRUE(badRole.err.contains(QStringLiteral("--roles: 'cantilever-z' is not a channel role")))
        << badRole.err.toStdString();

    const auto noSuchChannel = recordText(dir.path(), db, {"--roles", "q=cantilever-a"});
    EXPECT_EQ(noSuchChannel.exitCode, 2);
    EXPECT_TRUE(noSuchChannel.err.contains(QStringLiteral("no channel is named 'q'")))
        << noSuchChannel.err.toStdString();

    const auto noRoles = recordText(dir.path(), db, {"--mode", "panel-scan"});
    EXPECT_EQ(noRoles.exitCode, 2);
    EXPECT_TRUE(noRoles.err.contains(QStringLiteral("no channel plays cantilever-a, cantilever-b")))
        << noRoles.err.toStdString();
    EXPECT_TRUE(noRoles.err.contains(QStringLiteral("--roles a=cantilever-a,b=cantilever-b")))
        << noRoles.err.toStdString();
    EXPECT_TRUE(noRoles.out.isEmpty());
}
