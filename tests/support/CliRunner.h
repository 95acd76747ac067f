// Runs the built tactiscope-cli as a separate process, the way users and
// other tools do, and captures its exit code and output.
#pragma once

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace tactiscope::testing {

struct CliResult {
    int exitCode = -1;  // -1 when the process crashed or timed out
    QString out;
    QString err;
};

// With `environment` (this process's when none), e.g. a test shim
// preloaded.
inline CliResult runCli(const QStringList& arguments,
                        const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(TACTISCOPE_CLI), arguments);
    process.waitForFinished(120000);
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromUtf8(process.readAllStandardOutput()), QString::fromUtf8(process.readAllStandardError())};
}

// The one JSON object a command printed with --json (empty when none).
inline QJsonObject jsonOf(const CliResult& run)
{
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

}  // namespace tactiscope::testing
