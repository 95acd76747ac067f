// `tactiscope-cli emulate` as a separate process behind a real pty link,
// the probe the CLI tests record from (with a chosen fault when asked), and
// the session id a `record` summary line names.
#pragma once

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

inline std::int64_t sessionIdIn(const QString& summary)
{
    const auto match = QRegularExpression(QStringLiteral("^Recorded session (\\d+): ")).match(summary);
    return match.hasMatch() ? match.captured(1).toLongLong() : -1;
}

}  // namespace tactiscope::testing
