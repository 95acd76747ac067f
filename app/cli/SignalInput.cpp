// Opening a CSV file or a stored session for the signal tools.
#include "SignalInput.h"

#include "CliSupport.h"
#include "SessionArgument.h"
#include "core/io/CsvColumns.h"
#include "core/storage/CsvImport.h"
#include "core/storage/SessionStore.h"

#include <QFileInfo>

namespace tactiscope::cli {
namespace {

std::optional<int> importFile(const QString& path, const QString& command,
                              const core::storage::CsvImportOptions& options, SignalInput& input)
{
    if (!QFileInfo(path).isFile()) {
        printError(QStringLiteral("%1: no file %2").arg(command, quoted(path)));
        return kExitUsage;
    }
    input.scratch = std::make_unique<QTemporaryDir>();
    if (!input.scratch->isValid()) {
        printError(QStringLiteral("%1: cannot make a temporary folder: %2").arg(command, input.scratch->errorString()));
        return kExitFailure;
    }
    try {
        auto store = std::make_unique<core::storage::SessionStore>(
            input.scratch->filePath(QStringLiteral("read.tactiscope")).toStdString());
        input.session = core::storage::importCsv(*store, path.toStdString(), options).session;
        input.store = std::move(store);
    } catch (...) {
        return exitForReadError(path);
    }
    input.name = path;
    return std::nullopt;
}

}  // namespace

void addSignalInputOptions(QCommandLineParser& parser)
{
    parser.addOptions({
        {QStringLiteral("db"),
         QStringLiteral("Read a stored session instead of a file: the store (a station's file or a central "
                        "store's connection string)."),
         QStringLiteral("FILE|CONNINFO")},
        {QStringLiteral("session"), QStringLiteral("With --db: the session, its id, its uuid, or 'last'."),
         QStringLiteral("ID|UUID|last")},
        {QStringLiteral("rate"),
         QStringLiteral("FILE.csv without a time column: its rate in Hz (rows are consecutive samples)."),
         QStringLiteral("HZ")},
        {QStringLiteral("time-column"),
         QStringLiteral("FILE.csv: its time column (seconds), when not t, time, time_s or timestamp."),
         QStringLiteral("NAME")},
    });
}

std::optional<int> openSignalInput(const QCommandLineParser& parser, const QString& command, const QString& usage,
                                   SignalInput& input)
{
    const QStringList files = parser.positionalArguments();
    const QString db = parser.value(QStringLiteral("db"));
    const QString session = parser.value(QStringLiteral("session"));
    if (files.size() > 1) return usageError(QStringLiteral("%1 reads one FILE.csv").arg(command), usage);
    if (files.isEmpty() == db.isEmpty())
        return usageError(QStringLiteral("%1 reads FILE.csv or --db F --session N, one of them").arg(command), usage);
    if (!db.isEmpty() && session.isEmpty())
        return usageError(QStringLiteral("%1: --db goes with --session N").arg(command), usage);
    if (db.isEmpty() && !session.isEmpty())
        return usageError(QStringLiteral("%1: --session goes with --db F").arg(command), usage);
    if (files.isEmpty() && (parser.isSet(QStringLiteral("rate")) || parser.isSet(QStringLiteral("time-column"))))
        return usageError(
            QStringLiteral("%1: --rate and --time-column describe FILE.csv; a session has its own").arg(command),
            usage);
    if (!files.isEmpty()) {
        core::storage::CsvImportOptions options;
        if (const auto error = readCsvTimeOptions(parser, options)) return usageError(*error, usage);
        if (const auto exit = importFile(files.front(), command, options, input)) return exit;
    } else {
        if (!storeArgumentExists(db)) {
            printError(QStringLiteral("%1: no session store at %2").arg(command, db));
            return kExitUsage;
        }
        try {
            input.store = openStoreArgument(db, core::storage::Database::Access::ReadOnly);
            const auto id = resolveSession(*input.store, session);
            if (!id) {
                printError(QStringLiteral("%1: no session %2 in %3")
                               .arg(command, quoted(session), toQString(input.store->location())));
                return kExitUsage;
            }
            if (const auto refusal =
                    core::storage::oneDeviceRefusal(*input.store, *id, "the " + command.toStdString())) {
                printError(QStringLiteral("%1: %2").arg(command, toQString(*refusal)));
                return kExitUsage;
            }
            input.session = *id;
            input.name = QStringLiteral("session %1").arg(*id);
        } catch (const core::storage::StorageError& e) {
            return storageFailure(e, command + QStringLiteral(": "));
        }
    }
    try {
        const auto summary = input.store->session(input.session);
        input.channels = input.store->channels(input.session);
        input.sampleCount = input.store->sampleCount(input.session);
        input.sampleRate_hz = summary ? summary->sampleRate_hz : 0.0;
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e, command + QStringLiteral(": "));
    }
    return std::nullopt;
}

std::optional<std::size_t> findSignalChannel(const SignalInput& input, const QString& name, const QString& command,
                                             const std::vector<core::ChannelDescriptor>& computed)
{
    QStringList names;
    for (std::size_t c = 0; c < input.channels.size(); ++c) {
        const QString channel = toQString(input.channels[c].descriptor.name);
        if (channel == name) return c;
        names << channel;
    }
    for (const auto& channel : computed) names << toQString(channel.name);
    printError(QStringLiteral("%1: %2 has no channel %3; it has %4")
                   .arg(command, input.name, quoted(name), names.join(QStringLiteral(", "))));
    return std::nullopt;
}

ShownUnit shownUnit(const core::ChannelDescriptor& channel)
{
    switch (channel.kind) {
    case core::ChannelKind::Strain:
        return channel.unit.empty() ? ShownUnit{"µε", 1e6} : ShownUnit{channel.unit, 1.0};
    case core::ChannelKind::Force:
        return channel.unit == "N" ? ShownUnit{"mN", 1e3} : ShownUnit{channel.unit, 1.0};
    case core::ChannelKind::Capacitance:
        return channel.unit == "F" ? ShownUnit{"pF", 1e12} : ShownUnit{channel.unit, 1.0};
    case core::ChannelKind::Position:
        return channel.unit == "m" ? ShownUnit{"mm", 1e3} : ShownUnit{channel.unit, 1.0};
    default:
        return {channel.unit, 1.0};
    }
}

}  // namespace tactiscope::cli
