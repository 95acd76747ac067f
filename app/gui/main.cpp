// tactiscope: the workstation GUI. Starts streaming from the built-in
// simulator so it shows live data without any hardware attached, reports
// sessions a crash cut short, and can save a picture of itself (for the
// documentation and the display-scaling check).
#include "core/Version.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>
#include <QTimer>

#include <algorithm>
#include <optional>

namespace {

void nameApplication()
{
    QCoreApplication::setApplicationName(QStringLiteral("Tactiscope"));
    QCoreApplication::setOrganizationName(QStringLiteral("Tactiscope"));
    QCoreApplication::setApplicationVersion(QString::fromUtf8(tactiscope::core::versionString()));
}

// --help and --version answer without a display: a QApplication would
// abort where there is none (over ssh, in a script, in CI).
bool asksOnlyForText(int argc, char* argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray argument(argv[i]);
        if (argument == "-h" || argument == "--help" || argument == "--help-all" || argument == "-?" ||
            argument == "-v" || argument == "--version")
            return true;
    }
    return false;
}

void addOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QStringLiteral("Inspection workstation for cantilever tactile sensors."));
    parser.addHelpOption();
    parser.addVersionOption();
    const auto ids = tactiscope::devices::simulator::scenarioIds();
    QStringList scenarios;
    for (const auto& id : ids) scenarios << QString::fromStdString(id);
    parser.addOptions({
        {QStringLiteral("scenario"),
         QStringLiteral("Start on this simulator scenario: %1 (default %2).")
             .arg(scenarios.join(", "), QString::fromStdString(tactiscope::devices::simulator::kPanelScanScenario)),
         QStringLiteral("ID"), QString::fromStdString(tactiscope::devices::simulator::kPanelScanScenario)},
        {QStringLiteral("mode"),
         QStringLiteral("Start in this mode: %1 (general takes any scenario; one that cannot feed another "
                        "mode is refused with the reason, and the window stays in the scenario's).")
             .arg(QString::fromStdString(tactiscope::core::modeChoices())),
         QStringLiteral("MODE")},
        {QStringLiteral("screenshot"), QStringLiteral("Save the window as a PNG after a delay, then quit."),
         QStringLiteral("FILE")},
        {QStringLiteral("screenshot-delay-ms"), QStringLiteral("How long to stream before the screenshot (4000)."),
         QStringLiteral("MS"), QStringLiteral("4000")},
    });
}

}  // namespace

int main(int argc, char* argv[])
{
    if (asksOnlyForText(argc, argv)) {
        QCoreApplication text(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        addOptions(parser);
        parser.process(text);  // prints the help or the version and exits
        return 0;
    }
    QApplication app(argc, argv);
    nameApplication();
    QCommandLineParser parser;
    addOptions(parser);
    parser.process(app);
    const auto ids = tactiscope::devices::simulator::scenarioIds();
    QStringList scenarios;
    for (const auto& id : ids) scenarios << QString::fromStdString(id);
    const std::string scenario = parser.value(QStringLiteral("scenario")).toStdString();
    if (std::ranges::find(ids, scenario) == ids.end()) {
        QTextStream(stderr) << "tactiscope: unknown scenario " << QString::fromStdString(scenario) << "; one of "
                            << scenarios.join(", ") << '\n';
        return 2;
    }

    std::optional<tactiscope::core::Mode> mode;
    if (parser.isSet(QStringLiteral("mode"))) {
        mode = tactiscope::core::modeFromString(parser.value(QStringLiteral("mode")).toStdString());
        if (!mode) {
            QTextStream(stderr) << "tactiscope: unknown mode " << parser.value(QStringLiteral("mode")) << "; one of "
                                << QString::fromStdString(tactiscope::core::modeChoices()) << '\n';
            return 2;
        }
    }

    tactiscope::ui::MainWindow window;
    window.station().connectSource(std::make_unique<tactiscope::devices::simulator::SimulatorSource>(
        tactiscope::devices::simulator::makeScenario(scenario)));
    // Asked of the connected simulator, as the mode box asks it: a device's
    // own mode would otherwise win at its connect.
    if (mode) window.setMode(*mode);
    window.show();
    window.checkStore();

    if (parser.isSet(QStringLiteral("screenshot"))) {
        const QString file = parser.value(QStringLiteral("screenshot"));
        QTimer::singleShot(parser.value(QStringLiteral("screenshot-delay-ms")).toInt(), &window, [&window, file] {
            const bool saved = window.grab().save(file, "PNG");
            if (!saved) QTextStream(stderr) << "tactiscope: could not write " << file << '\n';
            QApplication::exit(saved ? 0 : 1);
        });
    }
    return QApplication::exec();
}
