// The sync subcommand: store-and-forward to a central store (CentralSync).
#include "SyncCommand.h"

#include "CliSupport.h"
#include "core/storage/central/CentralSync.h"

#include <QFileInfo>
#include <QTextStream>

namespace tactiscope::cli {
int runSync(const QStringList& arguments)
{
    const QString name = QStringLiteral("sync");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Send this station's finished and interrupted sessions to a site's central store, each whole or not at all; "
        "sessions the server already holds are skipped, so running it again sends only what is new, and a sync "
        "cut short is finished by the next one. The local store is only read.\n"
        "Prints one line: synced N sessions (X M samples), M already there. Samples count every channel's values. "
        "Exit 1 when the server cannot be reached or refuses a session (each named on stderr)."));
    parser.addOptions({
        {QStringLiteral("db"), QStringLiteral("This station's session store (required)."), QStringLiteral("FILE")},
        {QStringLiteral("server"),
         QStringLiteral("The central store: a postgresql:// URI or libpq key=value pairs (required)."),
         QStringLiteral("CONNINFO")},
        {QStringLiteral("station"),
         QStringLiteral("The station the sessions come from (default: the server role's name; a station role may "
                        "only use its own)."),
         QStringLiteral("NAME")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected %1").arg(quoted(parser.positionalArguments().front())), usage);
    for (const char* option : {"db", "server"})
        if (parser.value(QLatin1String(option)).isEmpty())
            return usageError(QStringLiteral("--%1 is required").arg(QLatin1String(option)), usage);
    const QString db = parser.value(QStringLiteral("db"));
    if (!QFileInfo::exists(db)) return usageError(QStringLiteral("%1 does not exist").arg(db), usage);
    if (parser.isSet(QStringLiteral("station")) && parser.value(QStringLiteral("station")).trimmed().isEmpty())
        return usageError(QStringLiteral("--station needs a name"), usage);

    core::storage::central::SyncOutcome outcome;
    try {
        core::storage::SessionStore local(db.toStdString(), core::storage::Database::Access::ReadOnly);
        core::storage::central::CentralStore central(parser.value(QStringLiteral("server")).toStdString());
        outcome = core::storage::central::syncToCentral(local, central,
                                                        parser.value(QStringLiteral("station")).toStdString());
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    for (const std::string& refusal : outcome.refused) printError(QString::fromStdString(refusal));
    for (const std::string& kept : outcome.keptAtStation)
        QTextStream(stderr) << "note: " << QString::fromStdString(kept) << '\n';
    QTextStream(stdout) << QString::fromStdString(core::storage::central::syncSummary(outcome)) << '\n';
    return outcome.refused.empty() ? kExitOk : kExitFailure;
}

}  // namespace tactiscope::cli
