// tactiscope-cli as a user runs it: a real process, its exit code, stdout,
// stderr and the files it writes.
#include "core/Version.h"
#include "support/CliRunner.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

QString firstLine(const QString& text)
{
    return text.section(QLatin1Char('\n'), 0, 0);
}

QStringList readLines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

}  // namespace

TEST(Cli, HelpListsTheCommands)
{
    const CliResult run = runCli({QStringLiteral("--help")});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_TRUE(run.out.startsWith(QStringLiteral("Usage: tactiscope-cli")));
    EXPECT_TRUE(run.out.contains(QStringLiteral("simulate")));
    // "help" and "help COMMAND", as most tools take them.
    const CliResult help = runCli({QStringLiteral("help")});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_EQ(help.out, run.out);
    const CliResult record = runCli({QStringLiteral("help"), QStringLiteral("record")});
    EXPECT_EQ(record.exitCode, 0);
    EXPECT_TRUE(record.out.startsWith(QStringLiteral("Usage: tactiscope-cli record"))) << record.out.toStdString();
    EXPECT_EQ(runCli({QStringLiteral("help"), QStringLiteral("frobnicate")}).exitCode, 2);
}

TEST(Cli, VersionPrintsTheBuildVersion)
{
    const CliResult run = runCli({QStringLiteral("--version")});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out.trimmed(),
              QStringLiteral("tactiscope-cli ") + QString::fromUtf8(tactiscope::core::versionString()));
}

TEST(Cli, MissingCommandUnknownCommandAndBadFlagExitWithUsage)
{
    const std::vector<std::pair<QStringList, QString>> cases{
        {{}, QStringLiteral("tactiscope-cli: no command given")},
        {{QStringLiteral("frobnicate")}, QStringLiteral("tactiscope-cli: unknown command 'frobnicate'")},
        {{QStringLiteral("--bogus")}, QStringLiteral("tactiscope-cli: unknown option '--bogus'")},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_EQ(firstLine(run.err), message);
        EXPECT_TRUE(run.err.contains(QStringLiteral("Usage: tactiscope-cli")));
        EXPECT_TRUE(run.out.isEmpty());
    }
}

// A command's error is its line, the usage line and where the options are:
// not a page of options that scrolls the error away.
TEST(Cli, SimulateRejectsBadArgumentsWithOneLineAndUsage)
{
    const std::vector<QStringList> cases{
        {QStringLiteral("simulate"), QStringLiteral("--bogus")},
        {QStringLiteral("simulate"), QStringLiteral("--seconds"), QStringLiteral("-1")},
        {QStringLiteral("simulate"), QStringLiteral("--seconds"), QStringLiteral("abc")},
        {QStringLiteral("simulate"), QStringLiteral("--seed"), QStringLiteral("-3")},
        {QStringLiteral("simulate"), QStringLiteral("--scenario"), QStringLiteral("moon-landing")},
        {QStringLiteral("simulate"), QStringLiteral("stray")},
    };
    for (const auto& arguments : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(firstLine(run.err).startsWith(QStringLiteral("tactiscope-cli: "))) << run.err.toStdString();
        EXPECT_TRUE(run.err.contains(QStringLiteral("Usage: tactiscope-cli simulate")));
        EXPECT_TRUE(run.err.endsWith(QStringLiteral("\nRun 'tactiscope-cli simulate --help' for its options.\n")))
            << run.err.toStdString();
        EXPECT_EQ(run.err.count(QLatin1Char('\n')), 3) << run.err.toStdString();
    }
}

TEST(Cli, SimulateWritesADeterministicCsvOfTheScan)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString first = dir.filePath(QStringLiteral("first.csv"));
    const QString again = dir.filePath(QStringLiteral("again.csv"));
    const QString other = dir.filePath(QStringLiteral("other.csv"));
    const QString common = QStringLiteral("simulate --seconds 2 --output");
    ASSERT_EQ(runCli(common.split(' ') + QStringList{first, QStringLiteral("--seed"), QStringLiteral("7")}).exitCode,
              0);
    ASSERT_EQ(runCli(common.split(' ') + QStringList{again, QStringLiteral("--seed"), QStringLiteral("7")}).exitCode,
              0);
    ASSERT_EQ(runCli(common.split(' ') + QStringList{other, QStringLiteral("--seed"), QStringLiteral("8")}).exitCode,
              0);

    const QStringList lines = readLines(first);
    ASSERT_EQ(lines.size(), 1001);  // header + 2 s × 500 Hz
    EXPECT_EQ(lines.front(), QStringLiteral("t [s],a [strain],b [strain]"));
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList cells = lines[i].split(QLatin1Char(','));
        ASSERT_EQ(cells.size(), 3);
        EXPECT_NEAR(cells[0].toDouble(), 0.002 * static_cast<double>(i - 1), 1e-12);
        bool ok = false;
        EXPECT_LT(std::abs(cells[1].toDouble(&ok)), 1e-3);  // strains, dimensionless
        EXPECT_TRUE(ok);
    }
    EXPECT_EQ(readLines(again), lines);
    EXPECT_NE(readLines(other), lines);
}

TEST(Cli, SimulateWritesToStandardOutputByDefault)
{
    const CliResult run = runCli({QStringLiteral("simulate"), QStringLiteral("--seconds"), QStringLiteral("0.1")});
    EXPECT_EQ(run.exitCode, 0);
    const QStringList lines = run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    EXPECT_EQ(lines.size(), 51);
    EXPECT_EQ(lines.front(), QStringLiteral("t [s],a [strain],b [strain]"));
}

TEST(Cli, SimulateFailsClearlyWhenTheOutputCannotBeCreated)
{
    const CliResult run =
        runCli({QStringLiteral("simulate"), QStringLiteral("--output"), QStringLiteral("/nonexistent-dir/x.csv")});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(
        firstLine(run.err).startsWith(QStringLiteral("tactiscope-cli: cannot create '/nonexistent-dir/x.csv'")));
}

// Every message that repeats a value the user gave quotes at most its first
// 40 characters and its length (issue 54: a 100 kB value was echoed whole):
// a command, an argument, a session, a number, an engine, a port's name.
TEST(Cli, APastedValueIsQuotedShortInEveryMessage)
{
    const QString pasted = QString(100000, QLatin1Char('7')) + QStringLiteral("x");
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    ASSERT_EQ(runCli({"simulate", "--seconds", "1", "--output", dir.filePath("s.csv")}).exitCode, 0);
    ASSERT_EQ(runCli({"import", dir.filePath("s.csv"), "--db", db}).exitCode, 0);
    const std::vector<QStringList> commands{
        {pasted},
        {"simulate", pasted},
        {"simulate", "--seconds", pasted},
        {"sessions", "--db", db, "show", pasted},
        {"sessions", "--db", db, pasted},
        {"detect", dir.filePath("s.csv"), "--engine", pasted},
        {"detect", dir.filePath("s.csv"), "--threshold", pasted},
        {"record", "--port", "a=/nonexistent", "--db", db, "--rate", pasted + QStringLiteral("=5")},
        {"import", dir.filePath("s.csv"), "--db", db, "--rate", pasted},
    };
    for (const QStringList& command : commands) {
        const CliResult result = runCli(command);
        const std::string shown = command.join(' ').left(60).toStdString();
        EXPECT_EQ(result.exitCode, 2) << shown << ": " << result.err.left(300).toStdString();
        EXPECT_TRUE(result.err.contains(QStringLiteral("(100001 characters)")))
            << shown << ": " << result.err.left(300).toStdString();
        EXPECT_LT(result.err.size(), 3000) << shown;
    }
}
