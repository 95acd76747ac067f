// A PDF's text as laid out on the page (poppler's pdftotext), so tests read
// what a person reading the report would read, and its first page as a
// picture (pdftoppm).
#pragma once

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
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

#ifdef TACTISCOPE_SCREENSHOT_DIR
// Renders a PDF's page `page` (1 for the first, 0 for the last) to
// <screenshots>/<name>.png for a person to look at (build/<preset>/screenshots,
// or TACTISCOPE_SCREENSHOT_DIR); true when the picture was written.
inline bool savePdfPage(const QString& pdf, const QString& name, int page = 1)
{
    if (page == 0) {  // the last: pdfinfo counts them
        QProcess info;
        info.start(QStringLiteral("pdfinfo"), {pdf});
        if (!info.waitForFinished(60000) || info.exitCode() != 0) return false;
        const QString said = QString::fromUtf8(info.readAllStandardOutput());
        const auto pages = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(said);
        if (!pages.hasMatch()) return false;
        page = pages.captured(1).toInt();
    }
    const QString override = qEnvironmentVariable("TACTISCOPE_SCREENSHOT_DIR");
    const QDir shots(override.isEmpty() ? QStringLiteral(TACTISCOPE_SCREENSHOT_DIR) : override);
    if (!shots.mkpath(QStringLiteral("."))) return false;
    const QString png = shots.filePath(name);
    const QString number = QString::number(page);
    return QProcess::execute(QStringLiteral("pdftoppm"),
                             {QStringLiteral("-png"), QStringLiteral("-r"), QStringLiteral("80"), QStringLiteral("-f"),
                              number, QStringLiteral("-l"), number, QStringLiteral("-singlefile"), pdf, png}) == 0 &&
           QFileInfo::exists(png + QStringLiteral(".png"));
}
inline bool savePdfFirstPage(const QString& pdf, const QString& name)
{
    return savePdfPage(pdf, name, 1);
}
#endif

}  // namespace tactiscope::testing
