// `tactiscope-cli emulate` as a separate process behind a real pty link,
// the probe the CLI tests record from (with a chosen fault when asked), and
// the session id a `record` summary line names.
#pragma once

#include "support/CliRunner.h"

#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <thread>

namespace tactiscope::testing {

// Starts `tactiscope-cli emulate` and waits for its link.
inline bool startEmulator(QProcess& emulator, const QString& link, const QStringList& extra = {})
{
    emulator.start(QStringLiteral(TACTISCOPE_CLI), QStringList{"emulate", "--link", link} + extra);
    if (!emulator.waitForStarted()) return false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!std::filesystem::is_symlink(link.toStdString()) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return std::filesystem::is_symlink(link.toStdString());
}

inline void stopEmulator(QProcess& emulator)
{
    emulator.terminate();  // SIGTERM: the emulator's clean stop
    emulator.waitForFinished(5000);
}

// `record` from an emulated probe of `scenario` into `db` for `seconds`,
// with extra record arguments; the emulator's link goes in `folder`.
// `extra`: the record command's further options; `emulatorExtra` the emulator's.
inline CliResult recordEmulated(const QString& folder, const QString& db, const QString& scenario, int seconds,
                                const QStringList& extra = {}, const QStringList& emulatorExtra = {})
{
    const QString link = folder + QStringLiteral("/probe");
    QProcess emulator;
    if (!startEmulator(emulator, link, QStringList{"--scenario", scenario, "--seed", "3"} + emulatorExtra))
        return {-1, {}, QStringLiteral("the emulator did not start")};
    auto result =
        runCli(QStringList{"record", "--port", link, "--seconds", QString::number(seconds), "--db", db} + extra);
    stopEmulator(emulator);
    return result;
}

inline std::int64_t sessionIdIn(const QString& summary)
{
    const auto match = QRegularExpression(QStringLiteral("^Recorded session (\\d+): ")).match(summary);
    return match.hasMatch() ? match.captured(1).toLongLong() : -1;
}

}  // namespace tactiscope::testing
