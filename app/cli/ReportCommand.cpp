// The report subcommand: arguments, the session, the PDF.
#include "ReportCommand.h"

#include "CliSupport.h"
#include "SessionArgument.h"
#include "core/report/ReportData.h"
#include "core/storage/Database.h"
#include "core/storage/SafeOutput.h"
#include "ui/report/ReportDocument.h"

#include <QDir>
#include <QFileInfo>
#include <QTextStream>

#include <cstring>
#include <stdexcept>

namespace tactiscope::cli {
namespace {

// One line, exit 2: the contract for bad input.
int badInput(const QString& message)
{
    printError(message);
    return kExitUsage;
}

}  // namespace

bool commandNeedsPainting(const char* command)
{
    return command && std::strcmp(command, "report") == 0;
}

int runReport(const QStringList& arguments)
{
    const QString name = QStringLiteral("report");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Write a session's inspection report as a PDF: subject, operator, date, device, sensor and "
                       "calibration, the verdict and who decided it, the key plot, and the defect sites, events, "
                       "readings and notes."));
    parser.addOptions({
        {QStringLiteral("db"),
         QStringLiteral("The session store (required): a station's file, or a central store's connection string "
                        "(postgresql://… or key=value with host= or dbname=)."),
         QStringLiteral("FILE|CONNINFO")},
        {QStringLiteral("session"), QStringLiteral("The session: its id, its uuid, or 'last' (required)."),
         QStringLiteral("ID|UUID|last")},
        {QStringLiteral("output"), QStringLiteral("The PDF to write (required)."), QStringLiteral("REPORT.pdf")},
        {QStringLiteral("from"), QStringLiteral("Start of the part reported, in session seconds."),
         QStringLiteral("S")},
        {QStringLiteral("to"), QStringLiteral("End of the part reported, in session seconds."), QStringLiteral("S")},
        {QStringLiteral("analysis"),
         QStringLiteral("Whose defects to report: 'live' (the recorded ones, the default) or a re-analysis saved "
                        "with analyze --save."),
         QStringLiteral("NAME")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    if (!parser.positionalArguments().isEmpty())
        return badInput(QStringLiteral("report: unexpected %1").arg(quoted(parser.positionalArguments().front())));
    for (const char* option : {"db", "session", "output"}) {
        if (parser.value(QLatin1String(option)).isEmpty())
            return badInput(QStringLiteral("report: --%1 is required").arg(QLatin1String(option)));
    }
    core::report::ReportRequest request;
    if (parser.isSet(QStringLiteral("analysis")))
        request.analysis = parser.value(QStringLiteral("analysis")).toStdString();
    if (request.analysis.empty()) return badInput(QStringLiteral("report: --analysis needs a name"));
    core::report::ReportRange& range = request.range;
    for (const auto& [option, bound] : {std::pair{"from", &range.from_s}, std::pair{"to", &range.to_s}}) {
        if (!parser.isSet(QLatin1String(option))) continue;
        *bound = parseNumber(parser.value(QLatin1String(option)));
        if (!*bound) return badInput(QStringLiteral("report: --%1 needs a number of seconds").arg(option));
    }
    const QString db = parser.value(QStringLiteral("db"));
    const QString output = parser.value(QStringLiteral("output"));
    if (!storeArgumentExists(db)) return badInput(QStringLiteral("report: no session store at %1").arg(db));
    try {
        core::storage::refuseOverwriting(output.toStdString(), core::storage::storeFiles(db.toStdString()));
    } catch (const core::storage::StorageError& e) {
        return badInput(QStringLiteral("report: %1").arg(toQString(e.what())));
    }

    core::report::ReportData data;
    try {
        const auto store = openStoreArgument(db, core::storage::Database::Access::ReadOnly);
        const auto id = resolveSession(*store, parser.value(QStringLiteral("session")));
        if (!id)
            return badInput(QStringLiteral("report: no session %1 in %2")
                                .arg(quoted(parser.value(QStringLiteral("session"))), toQString(store->location())));
        data = core::report::gatherReport(*store, *id, request);
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e, QStringLiteral("report: "));
    } catch (const std::invalid_argument& e) {
        return badInput(QStringLiteral("report: %1").arg(toQString(e.what())));
    }
    int pages = 0;
    try {
        pages = ui::writeReportPdf(data, output);
    } catch (const std::runtime_error& e) {
        printError(QStringLiteral("report: %1").arg(toQString(e.what())));
        return kExitFailure;
    }
    QTextStream(stdout) << QStringLiteral("session %1: %2 (%3 %4)\n")
                               .arg(data.session.id)
                               .arg(QDir::toNativeSeparators(output))
                               .arg(pages)
                               .arg(pages == 1 ? QStringLiteral("page") : QStringLiteral("pages"));
    return kExitOk;
}

}  // namespace tactiscope::cli
