// `tactiscope-cli emulate` as a user runs it: a real process behind a real
// pseudo-terminal, read here like a serial port.
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <thread>
#include <unistd.h>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

TEST(EmulateCli, StreamsTextLinesBehindTheLinkAndRemovesItAfterwards)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    QProcess emulator;
    emulator.start(QStringLiteral(TACTISCOPE_CLI), {"emulate", "--link", link, "--protocol", "text", "--scenario",
                                                    "palpation", "--rate", "200", "--seconds", "1"});
    ASSERT_TRUE(emulator.waitForStarted());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!std::filesystem::is_symlink(link.toStdString()) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(std::filesystem::is_symlink(link.toStdString()));

    const int fd = ::open(link.toLocal8Bit().constData(), O_RDONLY | O_NOCTTY);
    ASSERT_GE(fd, 0);
    std::string text;
    char buffer[256];
    while (text.size() < 300) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, 2000) <= 0) break;
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    ASSERT_TRUE(emulator.waitForFinished(10000));
    EXPECT_EQ(emulator.exitCode(), 0);
    EXPECT_EQ(text.rfind("high:", 0), 0u) << text;
    EXPECT_NE(text.find(" displacement:"), std::string::npos);
    EXPECT_TRUE(QString::fromUtf8(emulator.readAllStandardOutput()).contains("intact samples"));
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link.toStdString())));
}

// --seconds is the emulation's time: it ends then whether nobody opens the
// port, or a host records less than that and stops. (It used to wait for
// streaming time that never came, for ever.) The bound is generous: the
// point is that it ends at all, not how fast.
TEST(EmulateCli, EndsAfterItsSecondsWithOrWithoutAHost)
{
    QTemporaryDir dir;
    QProcess alone;
    ASSERT_TRUE(tactiscope::testing::startEmulator(alone, dir.filePath("alone"), {"--seconds", "1"}));
    EXPECT_TRUE(alone.waitForFinished(6000)) << "no host: still running";
    EXPECT_EQ(alone.exitCode(), 0);

    const QString link = dir.filePath("probe");
    QProcess served;
    ASSERT_TRUE(tactiscope::testing::startEmulator(served, link, {"--seconds", "2"}));
    const CliResult record = runCli({"record", "--port", link, "--seconds", "1", "--db", dir.filePath("s.tactiscope")});
    EXPECT_EQ(record.exitCode, 0) << record.err.toStdString();
    EXPECT_TRUE(served.waitForFinished(6000)) << "the host stopped after 1 s: still running";
    EXPECT_EQ(served.exitCode(), 0);
    if (served.state() != QProcess::NotRunning) tactiscope::testing::stopEmulator(served);
    if (alone.state() != QProcess::NotRunning) tactiscope::testing::stopEmulator(alone);
}

TEST(EmulateCli, BadOptionsExitWithCodeTwo)
{
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"emulate"}, "--link PATH is required"},
        {{"emulate", "--link", "/tmp/x", "--protocol", "morse"}, "--protocol must be binary or text"},
        {{"emulate", "--link", "/tmp/x", "--scenario", "moon"}, "unknown scenario 'moon'"},
        {{"emulate", "--link", "/tmp/x", "--garbage", "2"}, "--garbage must lie between 0 and 1"},
        {{"emulate", "--link", "/tmp/x", "--channels", "2.5"}, "--channels must be a whole number"},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(run.err.section('\n', 0, 0).contains(message)) << run.err.toStdString();
    }
}

TEST(PortsCli, ListsPortsAsJson)
{
    const CliResult run = runCli({"ports", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(run.out.startsWith("{\"serial\":["));
    EXPECT_TRUE(run.out.contains("\"hid\":["));
    EXPECT_EQ(runCli({"ports", "extra"}).exitCode, 2);
}
