// CSV column reader: CsvReader's rows, the wanted cells kept as numbers.
#include "core/io/CsvColumns.h"

#include "core/io/CsvReader.h"

#include <cmath>

namespace tactiscope::core::io {
namespace {

// The column `name`: by its exact header, else by a header naming it with an
// SI unit ("t [s]", "a [strain]", "force_n [N]"), whose numbers read as
// they are. A header with another unit ("t [ms]") is refused rather than
// read a thousand times off.
std::size_t columnOf(const CsvReader& reader, const std::string& name)
{
    const auto& header = reader.header();
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == name) return c;
    for (std::size_t c = 0; c < header.size(); ++c) {
        const ColumnHeader split = splitColumnHeader(header[c]);
        if (split.name != name || split.unit.empty()) continue;
        for (const char* si : {"s", "m", "N", "F", "strain", "count"})
            if (split.unit == si) return c;
        throw CsvError("'" + reader.path() + "': the column " + quotedForMessage(header[c]) + " is in " +
                       quotedForMessage(split.unit) + "; this command reads " + quotedForMessage(name) +
                       " in SI units (s, m, N, F or strain)");
    }
    return reader.column(name);  // throws, naming the columns there are
}

}  // namespace

CsvColumns readCsvColumns(const std::string& path, const std::vector<std::string>& wanted)
{
    CsvReader reader(path);
    CsvColumns result;
    result.header = reader.header();
    std::vector<std::size_t> wantedField;
    for (const auto& name : wanted) wantedField.push_back(columnOf(reader, name));
    result.columns.resize(wanted.size());
    std::vector<std::string_view> fields;
    while (reader.next(fields)) {
        for (std::size_t w = 0; w < wanted.size(); ++w) {
            const std::string_view cell = fields[wantedField[w]];
            const double value = reader.number(cell, wantedField[w]);
            if (std::isnan(value)) throw reader.cellError(cell, wantedField[w], "is not a number");
            result.columns[w].push_back(value);
        }
        result.lines.push_back(reader.lineNumber());
    }
    if (result.lines.empty()) throw CsvError("'" + path + "' has a header but no data rows");
    return result;
}

}  // namespace tactiscope::core::io
