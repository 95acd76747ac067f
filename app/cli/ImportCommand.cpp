// The import subcommand: options → CsvImportOptions, one line of result.
#include "ImportCommand.h"

#include "CliSupport.h"
#include "core/storage/CsvImport.h"

#include <QTextStream>

#include <optional>

namespace tactiscope::cli {

int runImport(const QStringList& arguments)
{
    const QString name = QStringLiteral("import");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Import a CSV recording as a new session.\n"
                       "Columns are 'name', 'name [unit]' or 'name (unit)'. Times come from a column named t, time,\n"
                       "time_s or timestamp (seconds; [ms] or [us] in its header scale it) or --time-column; without\n"
                       "one, give --rate. Missing rows become gaps. A Tactiscope export's X.meta.json beside X.csv\n"
                       "restores units, kinds, metadata, events, readings and annotations."));
    parser.addPositionalArgument(QStringLiteral("FILE.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("db"), QStringLiteral("The session store (required; created if missing)."),
         QStringLiteral("FILE")},
        {QStringLiteral("rate"), QStringLiteral("Sample rate in Hz: rows are consecutive samples."),
         QStringLiteral("HZ")},
        {QStringLiteral("time-column"), QStringLiteral("The time column (seconds)."), QStringLiteral("NAME")},
        {QStringLiteral("columns"), QStringLiteral("Data columns to import, in order (default: all but time)."),
         QStringLiteral("A,B,…")},
        {QStringLiteral("mode"),
         modeOptionText(QStringLiteral("(default: the metadata file's, else panel-scan when the columns can feed it, "
                                       "else general).")),
         QStringLiteral("MODE")},
        rolesOption(),
        unitsOption(QStringLiteral("the data columns, over their headers' (\"d [mm]\")")),
        {QStringLiteral("subject"), QStringLiteral("Panel or phantom id."), QStringLiteral("ID")},
        {QStringLiteral("operator"), QStringLiteral("Who recorded it."), QStringLiteral("NAME")},
        {QStringLiteral("notes"), QStringLiteral("Free text, e.g. the program it came from."), QStringLiteral("TEXT")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (parser.positionalArguments().size() != 1) return usageError(QStringLiteral("import needs one FILE.csv"), usage);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);

    core::storage::CsvImportOptions options;
    if (const auto error = readCsvTimeOptions(parser, options)) return usageError(*error, usage);
    if (parser.isSet(QStringLiteral("columns"))) {
        for (const QString& column : parser.value(QStringLiteral("columns")).split(QLatin1Char(',')))
            options.columns.push_back(column.trimmed().toStdString());
    }
    auto& metadata = options.metadata;
    if (parser.isSet(QStringLiteral("mode"))) {
        options.mode = parseMode(parser.value(QStringLiteral("mode")));
        if (!options.mode) return usageError(modeUsageError(), usage);
    }
    QString rolesError;
    const auto roles = parseRolesOption(parser, rolesError);
    if (!roles) return usageError(rolesError, usage);
    options.roles = *roles;
    QString unitsError;
    const auto units = parseUnitsOption(parser, unitsError);
    if (!units) return usageError(unitsError, usage);
    options.units = *units;
    metadata.subject = parser.value(QStringLiteral("subject")).toStdString();
    metadata.operatorName = parser.value(QStringLiteral("operator")).toStdString();
    metadata.notes = parser.value(QStringLiteral("notes")).toStdString();

    const QString input = parser.positionalArguments().front();
    std::optional<core::storage::SessionStore> store;
    try {
        store.emplace(parser.value(QStringLiteral("db")).toStdString());
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
        return kExitUsage;  // not a store, or a newer one
    }
    try {
        const auto result = core::storage::importCsv(*store, input.toStdString(), options);
        QTextStream out(stdout);
        out << "Imported " << input << " as session " << result.session << ": " << result.rows << " rows of "
            << result.channels.size() << (result.channels.size() == 1 ? " channel" : " channels") << " at "
            << QString::number(result.rate_hz, 'g', 12) << " Hz, " << result.lostSamples << " missing"
            << (result.usedSideFile ? ", metadata from the side file" : "") << '\n';
        for (const std::string& note : result.notes) out << "note: " << QString::fromStdString(note) << '\n';
    } catch (const core::io::CsvError& e) {
        printError(toQString(e.what()));
        return kExitUsage;
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e);  // busy, disk full (1) or what cannot be stored (2): nothing of the import was kept
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
