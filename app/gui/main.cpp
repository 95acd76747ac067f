// tactiscope: the workstation GUI. Starts streaming from the built-in
// simulator so it shows live data without any hardware attached.
#include "core/Version.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Tactiscope"));
    QApplication::setOrganizationName(QStringLiteral("Tactiscope"));
    QApplication::setApplicationVersion(QString::fromUtf8(tactiscope::core::versionString()));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Inspection workstation for cantilever tactile sensors."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.process(app);

    tactiscope::ui::MainWindow window;
    window.connectSource(std::make_unique<tactiscope::devices::simulator::SimulatorSource>(
        tactiscope::devices::simulator::makeScenario("panel-scan")));
    window.show();
    return QApplication::exec();
}
