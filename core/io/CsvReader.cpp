// CsvReader: line by line through a buffered stream, fields as views.
#include "core/io/CsvReader.h"

#include <cerrno>
#include <charconv>
#include <cstring>

namespace tactiscope::core::io {
namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '"')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '"' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

}  // namespace

void splitCsvLine(std::string_view line, char delimiter, std::vector<std::string_view>& fields)
{
    fields.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t at = line.find(delimiter, start);
        fields.push_back(trim(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
        if (at == std::string_view::npos) break;
        start = at + 1;
    }
}

CsvReader::CsvReader(const std::string& path)
    : m_path(path),
      m_file(path, std::ios::binary)
{
    if (!m_file) throw CsvError("cannot open '" + path + "': " + std::strerror(errno));
    if (!nextLine()) throw CsvError("'" + path + "' is empty");
    // A tab-separated header may hold commas in names ("force, N"), so tabs
    // win, then semicolons (a decimal-comma locale), then commas.
    for (const char candidate : {'\t', ';', ','}) {
        if (m_line.find(candidate) != std::string::npos) {
            m_delimiter = candidate;
            break;
        }
    }
    std::vector<std::string_view> fields;
    splitCsvLine(m_line, m_delimiter, fields);
    for (const auto field : fields) m_header.emplace_back(field);
}

bool CsvReader::nextLine()
{
    while (std::getline(m_file, m_line)) {
        ++m_lineNumber;
        m_bytesRead += m_line.size() + 1;
        const std::string_view line = trim(m_line);
        if (!line.empty() && line.front() != '#') return true;
    }
    if (m_file.bad()) throw CsvError("cannot read '" + m_path + "' past line " + std::to_string(m_lineNumber));
    return false;
}

std::size_t CsvReader::column(const std::string& name) const
{
    for (std::size_t c = 0; c < m_header.size(); ++c) {
        if (m_header[c] == name) return c;
    }
    std::string names;
    for (const auto& h : m_header) names += (names.empty() ? "" : ", ") + h;
    throw CsvError("'" + m_path + "' has no column '" + name + "' (columns: " + names + ")");
}

bool CsvReader::next(std::vector<std::string_view>& fields)
{
    if (!nextLine()) return false;
    splitCsvLine(m_line, m_delimiter, fields);
    if (fields.size() != m_header.size())
        throw CsvError("'" + m_path + "' line " + std::to_string(m_lineNumber) + " has " +
                       std::to_string(fields.size()) + " fields, the header has " + std::to_string(m_header.size()));
    return true;
}

double CsvReader::number(std::string_view cell, std::size_t column) const
{
    double value = 0.0;
    const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (cell.empty() || error != std::errc() || end != cell.data() + cell.size())
        throw CsvError("'" + m_path + "' line " + std::to_string(m_lineNumber) + ", column '" + m_header[column] +
                       "': '" + std::string(cell) + "' is not a number");
    return value;
}

}  // namespace tactiscope::core::io
