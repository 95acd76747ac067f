// Conventions shared by every tactiscope-cli subcommand: exit codes, error
// lines on stderr, and conversions between Qt and standard strings.
#pragma once

#include "core/NumberRanges.h"
#include "core/UnitScale.h"
#include "core/Vocabulary.h"
#include "core/modes/ChannelRoles.h"
#include "core/storage/CsvImport.h"
#include "core/storage/Database.h"
#include "devices/PortSource.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tactiscope::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // the command could not complete (I/O, device)
constexpr int kExitUsage = 2;    // bad arguments or bad input data

// Prints "tactiscope-cli: <message>" on stderr.
void printError(const QString& message);
// Prints the error line, a blank line and `usage` on stderr; returns kExitUsage.
int usageError(const QString& message, const QString& usage);

// Prints a store's error and gives its exit code: kExitUsage when the store
// is damaged (bad input), kExitFailure when it could not be reached or read.
int storageFailure(const core::storage::StorageError& error, const QString& prefix = {});

// Parses `arguments` (the subcommand's own, without the command name) with
// `parser`, which gets a --help option added. Returns the exit code when the
// command must end at once (0 after --help, 2 on a parse error), or nothing
// when it should go on.
std::optional<int> parseCommandLine(QCommandLineParser& parser, const QString& command, const QStringList& arguments);

// Usage text of a subcommand's parser, with its name in place of the program.
QString commandUsage(const QCommandLineParser& parser, const QString& command);

QString toQString(std::string_view text);

// SIGINT, SIGTERM and SIGHUP end long-running commands (emulate, record)
// cleanly: after installStopSignals(), stopRequested() turns true on any.
void installStopSignals();
bool stopRequested();

// --protocol: "binary" (also when empty, the default) or "text"; nothing
// for anything else.
std::optional<devices::WireProtocol> parseWireProtocol(const QString& text);

// --mode: the option's description ("panel-scan, palpation or capacitive"
// with `more` after it) and its value; nothing for an unknown mode.
QString modeOptionText(const QString& more);
std::optional<core::Mode> parseMode(const QString& text);
QString modeUsageError();  // "--mode must be panel-scan, palpation, capacitive or general"

// --roles NAME=ROLE,…: the option (record and import share it) and its
// value; a bad list is the usage error's text in `error`.
QCommandLineOption rolesOption();
std::optional<core::RoleAssignment> parseRolesOption(const QCommandLineParser& parser, QString& error);
// --units NAME=UNIT,…: the unit of channels that carry none (a text board's
// plain numbers, a CSV's bare columns). `whose` says what they are, for the help.
QCommandLineOption unitsOption(const QString& whose);
std::optional<core::UnitAssignment> parseUnitsOption(const QCommandLineParser& parser, QString& error);

// Inside a catch block of a command that read the file `path`: prints the
// error and returns the exit code. A file the importer refuses (io::CsvError,
// which names the file) or bad data in it (any other std::exception) is the
// user's to fix: 2; a store that failed (storage::StorageError): 1.
int exitForReadError(const QString& path);

// A value the user gave, quoted for a message: whole when short, else its
// first 40 characters and its length (core/text/ShortQuote.h).
QString quoted(const QString& value);

// Each of `names`' value of option --OPTION, given as VALUE for every one
// or NAME=VALUE for the one so named (--protocol board=text): the value
// named for it, else the one for every one, else none. None at all, with
// the usage error in `error`, for a name not in `names` (`hint` after it,
// such as how names are given), two values for every one, or one name
// given twice.
std::optional<std::vector<std::optional<QString>>> valuesByName(const QString& option, const QStringList& values,
                                                                const std::vector<std::string>& names,
                                                                const QString& noun, const QString& hint,
                                                                QString& error);

// "DEVICE/CHANNEL" split at its first '/'; none when either part is empty.
std::optional<std::pair<std::string, std::string>> deviceAndChannel(const std::string& key);

// Option --NAME's mains frequency, 50 or 60 Hz; nothing, with the usage
// error in `error`, for anything else.
std::optional<double> parseMainsFrequency(const QString& option, const QString& text, QString& error);

// --rate and --time-column of a CSV file read as import reads it (import,
// spectrum, health) into `options`; the usage error for a bad rate.
std::optional<QString> readCsvTimeOptions(const QCommandLineParser& parser, core::storage::CsvImportOptions& options);

// A finite number, or nothing when `text` is not one.
std::optional<double> parseNumber(const QString& text);
// Option --NAME's number when it lies in `range` (core/NumberRanges.h, the
// one place every range is kept), `fallback` when the option is not given;
// otherwise nothing, and `error` says the range and what was given:
// "--pre must be a number from 0 to 60 s, not '1e9'".
std::optional<double> numberInRange(const QCommandLineParser& parser, const char* option,
                                    const core::NumberRange& range, double fallback, QString& error);
// The same for one value `text` of option --NAME (one of a list, one a port).
std::optional<double> numberInRange(const QString& option, const QString& text, const core::NumberRange& range,
                                    QString& error);

}  // namespace tactiscope::cli
