// tactiscope-cli: headless entry point; see CliApplication for the commands.
#include "CliApplication.h"

#include <QCoreApplication>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("tactiscope-cli"));
    return tactiscope::cli::runCli(QCoreApplication::arguments().mid(1));
}
