// tactiscope-cli: headless entry point; see CliApplication for the commands.
#include "CliApplication.h"
#include "ReportCommand.h"

#include <QApplication>
#include <QCoreApplication>
#include <QStringList>

#include <cstdio>
#include <memory>

namespace {

// Qt's platform notes (e.g. "XDG_RUNTIME_DIR not set") would add lines to
// the CLI's one-line errors; only Qt's critical messages get through.
void quietQtMessages(QtMsgType type, const QMessageLogContext&, const QString& message)
{
    if (type == QtCriticalMsg || type == QtFatalMsg) fprintf(stderr, "%s\n", qPrintable(message));
}

}  // namespace

int main(int argc, char* argv[])
{
    // Most commands need Qt Core only. The report paints, which takes a GUI
    // application object: on the offscreen platform, so no display is needed.
    // It sees the program name alone, since a GUI application takes options
    // such as --session (X11 session management) for itself.
    std::unique_ptr<QCoreApplication> app;
    int guiArgc = 1;
    if (argc > 1 && tactiscope::cli::commandNeedsPainting(argv[1])) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
        qInstallMessageHandler(quietQtMessages);
        app = std::make_unique<QApplication>(guiArgc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("tactiscope-cli"));
    QStringList arguments;
    for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
    return tactiscope::cli::runCli(arguments);
}
