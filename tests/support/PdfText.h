// A PDF's text as laid out on the page (poppler's pdftotext), so tests read
// what a person reading the report would read.
#pragma once

#include <QProcess>
#include <QStandardPaths>
#include <QString>

namespace tactiscope::testing {

// Why a test that reads a PDF is skipped, or empty when it can run.
inline const char* pdfTextMissing()
{
    return QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty()
               ? "pdftotext (poppler-utils, in scripts/install-deps.sh) is needed to read the PDF"
               : "";
}

// Empty when pdftotext is missing or fails.
inline QString pdfText(const QString& pdf)
{
    QProcess process;
    process.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
    if (!process.waitForFinished(60000) || process.exitCode() != 0) return {};
    return QString::fromUtf8(process.readAllStandardOutput());
}

}  // namespace tactiscope::testing
