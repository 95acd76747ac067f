// The server subcommand: `server init CONNINFO`.
#include "ServerCommand.h"

#include "CliSupport.h"
#include "core/storage/central/CentralSchema.h"

#include <QTextStream>

namespace tactiscope::cli {

int runServer(const QStringList& arguments)
{
    const QString name = QStringLiteral("server");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Set up a site's central store on PostgreSQL.\n"
                       "server init CONNINFO creates or upgrades the schema and the roles tactiscope_station and "
                       "tactiscope_reviewer; running it again changes nothing. CONNINFO is libpq's: a "
                       "postgresql:// URI or key=value pairs; the password comes from ~/.pgpass, PGPASSFILE or "
                       "a service file, TLS from sslmode (e.g. sslmode=verify-full)."));
    parser.addPositionalArgument(QStringLiteral("init"), QStringLiteral("The action."));
    parser.addPositionalArgument(QStringLiteral("CONNINFO"), QStringLiteral("Where the server is."));
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2 || positional.front() != QStringLiteral("init"))
        return usageError(QStringLiteral("server needs: init CONNINFO"), commandUsage(parser, name));
    try {
        core::storage::central::PgConnection connection(positional.at(1).toStdString());
        core::storage::central::initCentralStore(connection);
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
    QTextStream(stdout) << "central store ready (schema " << core::storage::central::kCentralSchemaVersion
                        << "; roles tactiscope_station, tactiscope_reviewer)\n";
    return kExitOk;
}

}  // namespace tactiscope::cli
