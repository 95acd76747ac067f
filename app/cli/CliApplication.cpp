// Subcommand table and dispatch for tactiscope-cli.
#include "CliApplication.h"

#include "AnalyzeCommand.h"
#include "CalibrateCapacitiveCommand.h"
#include "CliSupport.h"
#include "ComplianceCommand.h"
#include "DetectCommand.h"
#include "EmulateCommand.h"
#include "FilterCommand.h"
#include "HealthCommand.h"
#include "ImportCommand.h"
#include "ModelCommand.h"
#include "PortsCommand.h"
#include "RecordCommand.h"
#include "ReportCommand.h"
#include "ServerCommand.h"
#include "SessionsCommand.h"
#include "ShuntCheckCommand.h"
#include "SimulateCommand.h"
#include "SpectrumCommand.h"
#include "SyncCommand.h"
#include "core/Version.h"

#include <QTextStream>

#include <array>

namespace tactiscope::cli {
namespace {

struct Command {
    const char* name;
    const char* summary;
    int (*run)(const QStringList& arguments);
};

constexpr std::array kCommands{
    Command{"analyze", "Re-run the detector on a stored panel-scan session (seed 000).", runAnalyze},
    Command{"calibrate-capacitive", "C0 and sensitivity of a capacitive beam (seed 002).", runCalibrateCapacitive},
    Command{"compliance", "Object stiffness from a compliance probe's forces (seed 001).", runCompliance},
    Command{"detect", "Find surface deflections in a CSV recording (seed 000).", runDetect},
    Command{"emulate", "A simulated probe behind a pseudo-terminal (try the serial path).", runEmulate},
    Command{"filter", "Write a CSV recording with one channel filtered (notch, low/high/band-pass).", runFilter},
    Command{"health", "Each channel's mains hum, noise floor, drift and clipped samples.", runHealth},
    Command{"import", "Import a CSV recording from another program as a session.", runImport},
    Command{"model", "What the sensor model gives for a profile (JSON).", runModel},
    Command{"ports", "List serial ports and HID devices.", runPorts},
    Command{"record", "Record a probe on a serial port into a session store.", runRecord},
    Command{"report", "Write a session's inspection report as a PDF.", runReport},
    Command{"server", "Set up a site's central store on PostgreSQL.", runServer},
    Command{"spectrum", "A channel's spectral density (unit/√Hz) and its strongest lines.", runSpectrum},
    Command{"sync", "Send this station's sessions to a site's central store.", runSync},
    Command{"sessions", "List, show, export or delete the sessions of a store.", runSessions},
    Command{"shunt-check", "Check a strain channel's bridge with the probe's shunt.", runShuntCheck},
    Command{"simulate", "Write a simulated recording as CSV.", runSimulate},
};

QString usage()
{
    QString text;
    QTextStream out(&text);
    out << "Usage: tactiscope-cli [--help] [--version] <command> [options]\n"
        << "       tactiscope-cli help [<command>]\n\n"
        << "Headless tools of Tactiscope, the tactile-sensor inspection workstation.\n\n"
        << "Commands:\n";
    for (const Command& command : kCommands)
        out << "  " << QString(command.name).leftJustified(22) << command.summary << '\n';
    out << "\nRun 'tactiscope-cli <command> --help' for a command's options.\n"
        << "Exit codes: 0 success, 1 the command failed, 2 bad arguments or input.\n";
    return text;
}

}  // namespace

int runCli(const QStringList& arguments)
{
    if (arguments.isEmpty()) return usageError(QStringLiteral("no command given"), usage());
    const QString& first = arguments.front();
    if (first == QLatin1String("--help") || first == QLatin1String("-h")) {
        QTextStream(stdout) << usage();
        return kExitOk;
    }
    if (first == QLatin1String("--version")) {
        QTextStream(stdout) << "tactiscope-cli " << core::versionString() << '\n';
        return kExitOk;
    }
    // "help" and "help record", as git and most tools take them.
    if (first == QLatin1String("help")) {
        if (arguments.size() == 1) {
            QTextStream(stdout) << usage();
            return kExitOk;
        }
        if (arguments.size() == 2 && !arguments[1].startsWith(QLatin1Char('-')))
            return runCli({arguments[1], QStringLiteral("--help")});
        return usageError(QStringLiteral("help takes one command's name"), usage());
    }
    if (first.startsWith(QLatin1Char('-')))
        return usageError(QStringLiteral("unknown option %1").arg(quoted(first)), usage());
    for (const Command& command : kCommands) {
        if (first == QLatin1String(command.name)) return command.run(arguments.mid(1));
    }
    return usageError(QStringLiteral("unknown command %1").arg(quoted(first)), usage());
}

}  // namespace tactiscope::cli
