// filter FILE.csv --channel NAME [--notch 50|60] [--lowpass HZ] [--highpass HZ]
//        [--order N] [--moving-average S] [--zero-phase] --output OUT.csv
#include "FilterCommand.h"

#include "CliSupport.h"
#include "SignalOptions.h"
#include "core/dsp/ChannelFilter.h"
#include "core/io/CsvReader.h"
#include "core/io/CsvTimeBase.h"
#include "core/storage/SafeOutput.h"
#include "core/text/NoNumber.h"
#include "core/text/NumberFormat.h"

#include <QTextStream>

#include <cmath>
#include <limits>

namespace tactiscope::cli {
namespace {

using core::dsp::FilterSettings;

struct FilterOptions {
    QString input;
    QString output;
    std::string channel;
    FilterSettings settings;
};

std::optional<QString> readOptions(const QCommandLineParser& parser, FilterOptions& options)
{
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1) return QStringLiteral("filter needs exactly one FILE.csv");
    options.input = files.front();
    options.output = parser.value(QStringLiteral("output"));
    if (options.output.isEmpty()) return QStringLiteral("filter: --output OUT.csv is required");
    options.channel = parser.value(QStringLiteral("channel")).toStdString();
    if (options.channel.empty()) return QStringLiteral("filter: --channel is required");
    FilterSettings& s = options.settings;
    if (auto error = readFilterSettings(parser, s)) return error;
    s.zeroPhase = parser.isSet(QStringLiteral("zero-phase"));
    if (s.empty() && parser.isSet(QStringLiteral("moving-average")))
        return QStringLiteral("filter: a moving average of 0 s is none: give it a length, or --notch, --lowpass or "
                              "--highpass");
    if (s.empty()) return QStringLiteral("filter: give --notch, --lowpass, --highpass or --moving-average");
    return std::nullopt;
}

std::size_t channelColumn(const core::io::CsvReader& reader, const std::string& channel)
{
    const auto& header = reader.header();
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == channel || core::io::splitColumnHeader(header[c]).name == channel) return c;
    return reader.column(channel);  // throws, naming the columns there are
}

double cellValue(const core::io::CsvReader& reader, std::string_view cell, std::size_t column)
{
    if (cell.empty() || core::text::spellsNoNumber(cell)) return std::numeric_limits<double>::quiet_NaN();
    return reader.number(cell, column);
}

void appendField(std::string& line, std::string_view field)
{
    if (field.find_first_of(",\"") == std::string_view::npos) {
        line += field;
        return;
    }
    line += '"';
    for (const char c : field) line += c == '"' ? std::string("\"\"") : std::string(1, c);
    line += '"';
}

// The channel's values in row order, with one NaN wherever rows are
// missing from the time grid: the filter restarts there.
struct ChannelRows {
    std::vector<double> series;
    std::vector<std::size_t> place;  // each row's index in `series`
};

ChannelRows readChannelRows(const std::string& path, std::size_t timeColumn, std::size_t column, double rate_hz)
{
    core::io::CsvReader reader(path);
    core::io::RowIndexer indexer(rate_hz, core::io::timeScale(reader.header()[timeColumn], path));
    ChannelRows rows;
    std::vector<std::string_view> fields;
    std::optional<std::uint64_t> previous;
    while (reader.next(fields)) {
        const std::uint64_t index = indexer.next(reader.number(fields[timeColumn], timeColumn), reader);
        if (previous && index > *previous + 1) rows.series.push_back(std::numeric_limits<double>::quiet_NaN());
        previous = index;
        rows.place.push_back(rows.series.size());
        rows.series.push_back(cellValue(reader, fields[column], column));
    }
    return rows;
}

void writeFiltered(const std::string& path, std::size_t column, const ChannelRows& rows,
                   const std::vector<double>& filtered, std::ostream& out)
{
    core::io::CsvReader reader(path);
    std::string line;
    for (std::size_t c = 0; c < reader.header().size(); ++c) {
        if (c > 0) line += ',';
        appendField(line, reader.header()[c]);
    }
    out << line << '\n';
    std::vector<std::string_view> fields;
    std::size_t row = 0;
    while (reader.next(fields)) {
        line.clear();
        for (std::size_t c = 0; c < fields.size(); ++c) {
            if (c > 0) line += ',';
            const double value = c == column ? filtered[rows.place[row]] : std::nan("");
            if (c == column && std::isfinite(value))
                core::text::appendShortest(line, value);
            else
                appendField(line, fields[c]);
        }
        out << line << '\n';
        ++row;
    }
}

}  // namespace

int runFilter(const QStringList& arguments)
{
    const QString name = QStringLiteral("filter");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Write FILE.csv again with one channel filtered, every other column as it was. The filter runs at the "
        "rate the time column gives (t, time, time_s or timestamp); it restarts after missing rows, as it "
        "cannot know what they held. Causal unless --zero-phase, which runs it forward and backward."));
    parser.addPositionalArgument(QStringLiteral("FILE.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("channel"), QStringLiteral("The channel to filter (required)."), QStringLiteral("NAME")},
    });
    parser.addOptions(filterOptions());
    parser.addOptions({
        {QStringLiteral("zero-phase"), QStringLiteral("Forward and backward: no delay, the magnitude squared.")},
        {QStringLiteral("output"), QStringLiteral("The CSV to write (required)."), QStringLiteral("OUT.csv")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    FilterOptions options;
    if (const auto error = readOptions(parser, options)) return usageError(*error, usage);
    const std::string input = options.input.toStdString();
    const std::string output = options.output.toStdString();
    try {
        core::storage::refuseOverwriting(output, {input});
    } catch (const core::storage::StorageError& e) {
        return usageError(toQString(e.what()), usage);
    }
    std::size_t rowsWritten = 0;
    double rate_hz = 0.0;
    try {
        const core::io::CsvReader header(input);
        const auto timeColumn = core::io::findTimeColumn(header.header());
        if (!timeColumn)
            throw core::io::CsvError("'" + input +
                                     "' has no time column (t, time, time_s or timestamp) to tell its sample rate");
        const std::size_t column = channelColumn(header, options.channel);
        if (column == *timeColumn)
            throw core::io::CsvError("'" + input + "': '" + options.channel +
                                     "' is the time column; --channel names a data column");
        rate_hz = core::io::measureRate(input, *timeColumn);
        if (const auto refusal = core::dsp::filterRefusal(options.settings, rate_hz))
            throw core::io::CsvError("'" + input + "' at " + core::text::formatShortest(rate_hz) + " Hz: " + *refusal);
        const ChannelRows rows = readChannelRows(input, *timeColumn, column, rate_hz);
        const std::vector<double> filtered = core::dsp::filterSeries(options.settings, rate_hz, rows.series);
        core::storage::writeAtomically(output,
                                       [&](std::ostream& out) { writeFiltered(input, column, rows, filtered, out); });
        rowsWritten = rows.place.size();
    } catch (...) {
        return exitForReadError(options.input);
    }
    const core::dsp::ChannelFilter filter(options.settings, rate_hz);
    QTextStream(stdout) << options.output << ": " << rowsWritten << " rows, " << toQString(options.channel) << " at "
                        << rate_hz << " Hz through " << toQString(options.settings.text()) << " (delay "
                        << QString::number(filter.delay_s() * 1e3, 'g', 3) << " ms)\n";
    return kExitOk;
}

}  // namespace tactiscope::cli
