// The server subcommand: `server init CONNINFO` and `server maintain
// CONNINFO`, the store's owner's.
#include "ServerCommand.h"

#include "CliSupport.h"
#include "core/storage/central/CentralMonths.h"
#include "core/storage/central/CentralSchema.h"

#include <QDateTime>
#include <QTextStream>

#include <optional>

namespace tactiscope::cli {
namespace {

namespace central = core::storage::central;

int initStore(central::PgConnection& connection)
{
    central::initCentralStore(connection);
    QTextStream(stdout) << "central store ready (schema " << central::kCentralSchemaVersion
                        << "; roles tactiscope_station, tactiscope_reviewer)\n";
    return kExitOk;
}

QString joined(const QStringList& months)
{
    return months.isEmpty() ? QStringLiteral("none") : months.join(QStringLiteral(", "));
}

QString joined(const std::vector<std::string>& months)
{
    QStringList list;
    for (const std::string& m : months) list << QString::fromStdString(m);
    return joined(list);
}

// Why this connection cannot keep the store: a read replica, or a login
// that does not own it. Nothing when it can.
std::optional<QString> notTheOwnersPrimary(central::PgConnection& connection)
{
    const auto r =
        connection.query("SELECT pg_is_in_recovery(), to_regclass('sessions') IS NULL OR "
                         "pg_has_role((SELECT relowner FROM pg_class WHERE oid = to_regclass('sessions')), 'MEMBER')");
    const QString where = QString::fromStdString(connection.location());
    if (r.text(0, 0) == "t")
        return QStringLiteral("%1 is a read-only replica of the central store; run server on the primary").arg(where);
    if (r.text(0, 1) != "t")
        return QStringLiteral("the login %1 does not own the central store at %2; server is its owner's")
            .arg(QString::fromStdString(connection.user()), where);
    return std::nullopt;
}

int maintainStore(central::PgConnection& connection, int ahead, const QString& detachBefore, const QString& attach)
{
    QTextStream out(stdout);
    if (!attach.isEmpty()) {
        if (central::attachMonth(connection, attach.toStdString()))
            out << "attached " << attach << ": its sessions' samples are in the store again\n";
        else
            out << attach << " is in the store already\n";
    }
    const auto made = central::makeComingMonths(connection, ahead);
    out << "months made: " << joined(made) << "\n";
    if (!detachBefore.isEmpty()) {
        const auto detached = central::detachMonthsBefore(connection, detachBefore.toStdString());
        out << "months detached: " << joined(detached) << "\n";
        for (const std::string& month : detached) {
            const QString suffix = QString::fromStdString(month).replace('-', '_');
            out << "  " << QString::fromStdString(month) << ": its sessions stay listed; its tables months.chunks_"
                << suffix << " and months.lod_" << suffix
                << " stay in the database until archived (pg_dump --table 'months.*_" << suffix << "') and dropped\n";
        }
    }
    QStringList kept;
    for (const central::StoreMonth& m : central::storeMonths(connection))
        kept << QString::fromStdString(m.month) + (m.attached ? QString() : QStringLiteral(" (detached)"));
    out << "months in the store: " << joined(kept) << "\n";
    return kExitOk;
}

}  // namespace

int runServer(const QStringList& arguments)
{
    const QString name = QStringLiteral("server");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Set up and keep a site's central store on PostgreSQL, as its owner.\n"
                       "server init CONNINFO creates or upgrades the schema and the roles tactiscope_station and "
                       "tactiscope_reviewer; running it again changes nothing.\n"
                       "server maintain CONNINFO makes the tables of this month and the coming ones (samples are "
                       "kept by the month their session started in) and, when asked, detaches old months or "
                       "attaches one again; safe to run from cron, e.g. daily.\n"
                       "CONNINFO is libpq's: a postgresql:// URI or key=value pairs; the password comes from "
                       "~/.pgpass, PGPASSFILE or a service file, TLS from sslmode (e.g. sslmode=verify-full)."));
    parser.addPositionalArgument(QStringLiteral("action"), QStringLiteral("init or maintain."));
    parser.addPositionalArgument(QStringLiteral("CONNINFO"), QStringLiteral("Where the server is."));
    const QCommandLineOption ahead(QStringLiteral("months-ahead"),
                                   QStringLiteral("maintain: make the tables of this many months after this one "
                                                  "(default 2, at most 12)."),
                                   QStringLiteral("N"), QStringLiteral("2"));
    const QCommandLineOption detach(QStringLiteral("detach-before"),
                                    QStringLiteral("maintain: detach every month before YYYY-MM (not after this "
                                                   "month) from the store, to be archived."),
                                    QStringLiteral("YYYY-MM"));
    const QCommandLineOption attach(QStringLiteral("attach"),
                                    QStringLiteral("maintain: attach the detached month YYYY-MM again."),
                                    QStringLiteral("YYYY-MM"));
    parser.addOptions({ahead, detach, attach});
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QStringList positional = parser.positionalArguments();
    const QString action = positional.value(0);
    if (positional.size() != 2 || (action != QStringLiteral("init") && action != QStringLiteral("maintain")))
        return usageError(QStringLiteral("server needs: init CONNINFO, or maintain CONNINFO"),
                          commandUsage(parser, name));
    const bool maintain = action == QStringLiteral("maintain");
    if (!maintain && (parser.isSet(ahead) || parser.isSet(detach) || parser.isSet(attach)))
        return usageError(QStringLiteral("--months-ahead, --detach-before and --attach are maintain's"),
                          commandUsage(parser, name));
    bool numeric = false;
    const int monthsAhead = parser.value(ahead).toInt(&numeric);
    if (!numeric || monthsAhead < 0 || monthsAhead > 12)
        return usageError(
            QStringLiteral("--months-ahead needs a whole number from 0 to 12, not '%1'").arg(parser.value(ahead)),
            commandUsage(parser, name));
    for (const QCommandLineOption& month : {detach, attach})
        if (parser.isSet(month) && !central::isMonthText(parser.value(month).toStdString()))
            return usageError(QStringLiteral("--%1 needs a month such as 2026-01, not '%2'")
                                  .arg(month.names().front(), parser.value(month)),
                              commandUsage(parser, name));
    // (The server's clock decides too; this one catches a typo before connecting.)
    const QString thisMonth = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM"));
    if (parser.isSet(detach) && parser.value(detach) > thisMonth)
        return usageError(QStringLiteral("--detach-before %1 would detach this month (%2), whose sessions are still "
                                         "being sent; detach only months that have ended")
                              .arg(parser.value(detach), thisMonth),
                          commandUsage(parser, name));
    if (parser.isSet(detach) && parser.isSet(attach) && parser.value(attach) < parser.value(detach))
        return usageError(QStringLiteral("--attach %1 and --detach-before %2 contradict each other: the month "
                                         "would be attached and detached again")
                              .arg(parser.value(attach), parser.value(detach)),
                          commandUsage(parser, name));
    try {
        central::PgConnection connection(positional.at(1).toStdString());
        if (const auto refusal = notTheOwnersPrimary(connection)) {
            printError(*refusal);
            return kExitFailure;
        }
        // Attaching a month checks every row of it: no product time limit.
        connection.allowLongStatements();
        return maintain ? maintainStore(connection, monthsAhead, parser.value(detach), parser.value(attach))
                        : initStore(connection);
    } catch (const core::storage::StorageError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitFailure;
    }
}

}  // namespace tactiscope::cli
