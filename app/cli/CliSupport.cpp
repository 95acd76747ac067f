// Error reporting and parsing helpers for tactiscope-cli.
#include "CliSupport.h"

#include "core/io/CsvColumns.h"
#include "core/storage/Database.h"
#include "core/storage/central/PgConnection.h"
#include "core/text/ShortQuote.h"

#include <QRegularExpression>
#include <QTextStream>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>

namespace tactiscope::cli {
namespace {

std::atomic<bool> g_stopRequested = false;

extern "C" void onStopSignal(int)
{
    g_stopRequested = true;
}

}  // namespace

std::optional<devices::WireProtocol> parseWireProtocol(const QString& text)
{
    if (text.isEmpty() || text == QLatin1String("binary")) return devices::WireProtocol::Binary;
    if (text == QLatin1String("text")) return devices::WireProtocol::Text;
    return std::nullopt;
}

void installStopSignals()
{
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    std::signal(SIGHUP, onStopSignal);  // the terminal was closed: end as cleanly as on Ctrl+C
}

bool stopRequested()
{
    return g_stopRequested;
}

void printError(const QString& message)
{
    // A message may quote what was typed: never a connection's password.
    QTextStream(stderr) << "tactiscope-cli: "
                        << QString::fromStdString(core::storage::central::withoutPasswords(message.toStdString()))
                        << '\n';
}

int storageFailure(const core::storage::StorageError& error, const QString& prefix)
{
    printError(prefix + QString::fromStdString(error.what()));
    return dynamic_cast<const core::storage::StoreInputError*>(&error) ? kExitUsage : kExitFailure;
}

int usageError(const QString& message, const QString& usage)
{
    printError(message);
    // A command's usage is a page of options: its first line and where the
    // rest is, so the error stays on screen. The program's own (the list
    // of commands) is short and is the help itself.
    static const QRegularExpression command(QStringLiteral("^Usage: tactiscope-cli ([a-z-]+)"));
    const auto match = command.match(usage);
    if (!match.hasMatch()) {
        QTextStream(stderr) << '\n' << usage;
        return kExitUsage;
    }
    QTextStream(stderr) << usage.section(QLatin1Char('\n'), 0, 0) << "\nRun 'tactiscope-cli " << match.captured(1)
                        << " --help' for its options.\n";
    return kExitUsage;
}

QString commandUsage(const QCommandLineParser& parser, const QString& command)
{
    // helpText() begins "Usage: <path of the binary> [options]"; show the
    // program's plain name and the subcommand instead.
    QString text = parser.helpText();
    const qsizetype programStart = text.indexOf(QLatin1Char(' ')) + 1;
    const qsizetype programEnd = text.indexOf(QLatin1Char(' '), programStart);
    if (programStart > 0 && programEnd > programStart)
        text.replace(programStart, programEnd - programStart, QStringLiteral("tactiscope-cli ") + command);
    return text;
}

std::optional<int> parseCommandLine(QCommandLineParser& parser, const QString& command, const QStringList& arguments)
{
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help and exit."));
    parser.addOption(help);
    // QCommandLineParser expects the program name first.
    if (!parser.parse(QStringList{QStringLiteral("tactiscope-cli")} + arguments))
        return usageError(parser.errorText(), commandUsage(parser, command));
    if (parser.isSet(help)) {
        QTextStream(stdout) << commandUsage(parser, command);
        return kExitOk;
    }
    return std::nullopt;
}

std::optional<double> parseNumber(const QString& text)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

QString quoted(const QString& value)
{
    return toQString(core::text::quoteShort(value.toStdString()));
}

std::optional<std::pair<std::string, std::string>> deviceAndChannel(const std::string& key)
{
    const auto slash = key.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == key.size()) return std::nullopt;
    return std::pair{key.substr(0, slash), key.substr(slash + 1)};
}

std::optional<double> numberInRange(const QCommandLineParser& parser, const char* option,
                                    const core::NumberRange& range, double fallback, QString& error)
{
    const QString name = QLatin1String(option);
    if (!parser.isSet(name)) return fallback;
    return numberInRange(name, parser.value(name), range, error);
}

std::optional<double> numberInRange(const QString& option, const QString& text, const core::NumberRange& range,
                                    QString& error)
{
    if (const auto value = parseNumber(text); value && range.holds(*value)) return value;
    error = QStringLiteral("--%1 must be a number %2, not %3").arg(option, toQString(range.text()), quoted(text));
    return std::nullopt;
}

QString toQString(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString modeOptionText(const QString& more)
{
    return toQString(core::modeChoices()) + QStringLiteral(" ") + more;
}

std::optional<core::Mode> parseMode(const QString& text)
{
    return core::modeFromString(text.toStdString());
}

QString modeUsageError()
{
    return QStringLiteral("--mode must be %1").arg(toQString(core::modeChoices()));
}

QCommandLineOption rolesOption()
{
    return {QStringLiteral("roles"),
            QStringLiteral("What each channel is to the mode, by channel name: NAME=ROLE,… with the roles %1 "
                           "(e.g. a=cantilever-a,b=cantilever-b); a channel not named keeps the device's role.")
                .arg(toQString(core::channelRoleChoices())),
            QStringLiteral("LIST")};
}

std::optional<core::RoleAssignment> parseRolesOption(const QCommandLineParser& parser, QString& error)
{
    if (!parser.isSet(QStringLiteral("roles"))) return core::RoleAssignment{};
    try {
        return core::parseRoleAssignment(parser.value(QStringLiteral("roles")).toStdString());
    } catch (const std::invalid_argument& e) {
        error = QStringLiteral("--roles: %1").arg(QString::fromStdString(e.what()));
        return std::nullopt;
    }
}

QCommandLineOption unitsOption(const QString& whose)
{
    return {QStringLiteral("units"),
            QStringLiteral(
                "The unit of %1, by channel name: NAME=UNIT,… (e.g. a=µε,b=µε). Strain (strain, µε), "
                "force (N, kN, mN, µN), length (m, cm, mm, µm) and capacitance (F, nF, pF, fF) are stored in SI; a "
                "channel with no unit is a plain number, which no mode reads as a strain or a force.")
                .arg(whose),
            QStringLiteral("LIST")};
}

std::optional<core::UnitAssignment> parseUnitsOption(const QCommandLineParser& parser, QString& error)
{
    if (!parser.isSet(QStringLiteral("units"))) return core::UnitAssignment{};
    try {
        return core::parseUnitAssignment(parser.value(QStringLiteral("units")).toStdString());
    } catch (const std::invalid_argument& e) {
        error = QStringLiteral("--units: %1").arg(QString::fromStdString(e.what()));
        return std::nullopt;
    }
}

int exitForReadError(const QString& path)
{
    try {
        throw;
    } catch (const core::io::CsvError& e) {
        printError(toQString(e.what()));
        return kExitUsage;
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
        return kExitFailure;
    } catch (const std::exception& e) {
        printError(QStringLiteral("'%1': %2").arg(path, toQString(e.what())));
        return kExitUsage;
    }
}

std::optional<QString> readCsvTimeOptions(const QCommandLineParser& parser, core::storage::CsvImportOptions& options)
{
    if (parser.isSet(QStringLiteral("rate"))) {
        QString error;
        options.rate_hz = numberInRange(parser, "rate", core::kSampleRateRange, 0.0, error);
        if (!options.rate_hz) return error;
    }
    options.timeColumn = parser.value(QStringLiteral("time-column")).toStdString();
    return std::nullopt;
}

std::optional<std::vector<std::optional<QString>>> valuesByName(const QString& option, const QStringList& values,
                                                                const std::vector<std::string>& names,
                                                                const QString& noun, const QString& hint,
                                                                QString& error)
{
    std::optional<QString> forEvery;
    std::vector<std::optional<QString>> named(names.size());
    for (const QString& value : values) {
        const auto equals = value.indexOf(QLatin1Char('='));
        if (equals < 0) {
            if (forEvery) {
                error = QStringLiteral("--%1: give one value for every %2, or NAME=VALUE once for each %2 named (%3)")
                            .arg(option, noun, hint);
                return std::nullopt;
            }
            forEvery = value;
            continue;
        }
        const std::string name = value.left(equals).toStdString();
        const auto found = std::ranges::find(names, name);
        if (name.empty() || found == names.end()) {
            error = QStringLiteral("--%1: no %2 is named %3 (%4)").arg(option, noun, quoted(value.left(equals)), hint);
            return std::nullopt;
        }
        auto& slot = named[static_cast<std::size_t>(found - names.begin())];
        if (slot) {
            error = QStringLiteral("--%1: %2 is given twice").arg(option, quoted(value.left(equals)));
            return std::nullopt;
        }
        slot = value.mid(equals + 1);
    }
    for (auto& slot : named)
        if (!slot) slot = forEvery;
    return named;
}

std::optional<double> parseMainsFrequency(const QString& option, const QString& text, QString& error)
{
    if (text == QStringLiteral("50") || text == QStringLiteral("60")) return text.toDouble();
    error = QStringLiteral("--%1 is the mains frequency, 50 or 60, not %2").arg(option, quoted(text));
    return std::nullopt;
}

}  // namespace tactiscope::cli
