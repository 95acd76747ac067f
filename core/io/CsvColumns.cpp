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
// Named with its unit ("t [ms]"), it is refused the same way.
std::size_t columnOf(const CsvReader& reader, const std::string& name)
{
    const auto& header = reader.header();
    const auto siOnly = [&](std::size_t c) {
        const ColumnHeader split = splitColumnHeader(header[c]);
        if (split.unit.empty()) return c;
        for (const char* si : {"s", "m", "N", "F", "strain", "count"})
            if (split.unit == si) return c;
        throw CsvError("'" + reader.path() + "': the column " + quotedForMessage(header[c]) + " is in " +
                       quotedForMessage(split.unit) + "; this command reads " + quotedForMessage(split.name) +
                       " in SI units (s, m, N, F or strain)");
    };
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == name) return siOnly(c);
    for (std::size_t c = 0; c < header.size(); ++c)
        if (const ColumnHeader split = splitColumnHeader(header[c]); split.name == name && !split.unit.empty())
            return siOnly(c);
    return reader.column(name);  // throws, naming the columns there are
}

}  // namespace

CsvColumnReader::CsvColumnReader(const std::string& path, const std::vector<std::string>& wanted)
    : m_reader(std::make_unique<CsvReader>(path))
{
    for (const auto& name : wanted) m_fields.push_back(columnOf(*m_reader, name));
}

CsvColumnReader::~CsvColumnReader() = default;

const std::vector<std::string>& CsvColumnReader::header() const
{
    return m_reader->header();
}

std::size_t CsvColumnReader::read(std::size_t maxRows, std::vector<std::vector<double>>& columns,
                                  std::vector<std::size_t>& lines)
{
    columns.resize(m_fields.size());
    // Sized once for the block, filled by index: no growth per row.
    for (auto& column : columns) column.resize(maxRows);
    lines.resize(maxRows);
    std::size_t rows = 0;
    while (rows < maxRows && m_reader->next(m_row)) {
        for (std::size_t w = 0; w < m_fields.size(); ++w) {
            const std::string_view cell = m_row[m_fields[w]];
            const double value = m_reader->number(cell, m_fields[w]);
            if (std::isnan(value)) throw m_reader->cellError(cell, m_fields[w], "is not a number");
            columns[w][rows] = value;
        }
        lines[rows++] = m_reader->lineNumber();
    }
    for (auto& column : columns) column.resize(rows);
    lines.resize(rows);
    return rows;
}

CsvColumns readCsvColumns(const std::string& path, const std::vector<std::string>& wanted)
{
    CsvColumnReader reader(path, wanted);
    CsvColumns result;
    result.header = reader.header();
    result.columns.resize(wanted.size());
    constexpr std::size_t kBlock = 65536;
    std::vector<std::vector<double>> block;
    std::vector<std::size_t> lines;
    while (reader.read(kBlock, block, lines) > 0) {
        for (std::size_t w = 0; w < wanted.size(); ++w)
            result.columns[w].insert(result.columns[w].end(), block[w].begin(), block[w].end());
        result.lines.insert(result.lines.end(), lines.begin(), lines.end());
    }
    if (result.lines.empty()) throw CsvError("'" + path + "' has a header but no data rows");
    return result;
}

}  // namespace tactiscope::core::io
