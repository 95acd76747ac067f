// CsvReader: lines found in a large read buffer, fields as views.
#include "core/io/CsvReader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
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

// The line terminator: CR alone when the file's start has CRs and no LF.
char lineEndOf(std::ifstream& file)
{
    char start[65536];
    file.read(start, sizeof start);
    const std::string_view text(start, static_cast<std::size_t>(file.gcount()));
    file.clear();
    file.seekg(0);
    return text.find('\n') == std::string_view::npos && text.find('\r') != std::string_view::npos ? '\r' : '\n';
}

}  // namespace

std::string quotedForMessage(std::string_view text)
{
    constexpr std::size_t kShown = 80;
    if (text.size() <= kShown) return "'" + std::string(text) + "'";
    return "'" + std::string(text.substr(0, kShown)) + "…' (" + std::to_string(text.size()) + " characters)";
}

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

namespace {

// The read buffer: large enough that the file system's read-ahead pays,
// small enough to stay in a core's cache levels while its rows are parsed.
constexpr std::size_t kReadBuffer = std::size_t{1} << 20;

}  // namespace

CsvReader::CsvReader(const std::string& path)
    : m_path(path),
      m_file(path, std::ios::binary),
      m_buffer(kReadBuffer)
{
    if (!m_file) throw CsvError("cannot open '" + path + "': " + std::strerror(errno));
    m_lineEnd = lineEndOf(m_file);
    if (!nextLine()) throw CsvError("'" + path + "' is empty");
    readHeader();
}

void CsvReader::readHeader()
{
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
    if (fields.size() > 1 && fields.back().empty()) {
        fields.pop_back();
        m_trailingDelimiter = true;
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
        if (fields[c].empty())
            throw CsvError("'" + m_path + "': column " + std::to_string(c + 1) + " of the header has no name");
        for (std::size_t before = 0; before < c; ++before) {
            if (fields[before] == fields[c])
                throw CsvError("'" + m_path + "': the header names " + quotedForMessage(fields[c]) +
                               " twice (columns " + std::to_string(before + 1) + " and " + std::to_string(c + 1) + ")");
        }
        m_header.emplace_back(fields[c]);
    }
}

// The next line without its terminator, as a view into the buffer (valid
// until the next call); the last line may lack a terminator.
bool CsvReader::nextRawLine(std::string_view& line)
{
    while (true) {
        const char* start = m_buffer.data() + m_position;
        const std::size_t available = m_filled - m_position;
        if (const void* end = std::memchr(start, m_lineEnd, available)) {
            line = std::string_view(start, static_cast<std::size_t>(static_cast<const char*>(end) - start));
            m_position += line.size() + 1;
            return true;
        }
        if (m_endOfFile) {
            if (available == 0) return false;
            line = std::string_view(start, available);
            m_position = m_filled;
            return true;
        }
        // The unfinished line to the front (a line longer than the buffer
        // doubles it), then more of the file after it.
        std::memmove(m_buffer.data(), start, available);
        m_position = 0;
        m_filled = available;
        if (m_filled == m_buffer.size()) m_buffer.resize(2 * m_buffer.size());
        m_file.read(m_buffer.data() + m_filled, static_cast<std::streamsize>(m_buffer.size() - m_filled));
        if (m_file.bad()) throw CsvError("cannot read '" + m_path + "' past line " + std::to_string(m_lineNumber));
        const auto got = static_cast<std::size_t>(m_file.gcount());
        m_filled += got;
        if (got == 0 || m_file.eof()) m_endOfFile = true;
    }
}

bool CsvReader::nextLine()
{
    while (nextRawLine(m_line)) {
        ++m_lineNumber;
        m_bytesRead += m_line.size() + 1;
        constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";  // UTF-8's, written by spreadsheet programs
        if (m_lineNumber == 1 && m_line.starts_with(kByteOrderMark)) m_line.remove_prefix(kByteOrderMark.size());
        const std::string_view line = trim(m_line);
        if (!line.empty() && line.front() != '#') return true;
    }
    return false;
}

ColumnHeader splitColumnHeader(const std::string& header)
{
    for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
        const auto at = header.rfind(open);
        if (at != std::string::npos && at > 0 && header.back() == close) {
            std::string name = header.substr(0, at);
            while (!name.empty() && name.back() == ' ') name.pop_back();
            return {name, header.substr(at + 1, header.size() - at - 2)};
        }
    }
    return {header, ""};
}

std::size_t CsvReader::column(const std::string& name) const
{
    for (std::size_t c = 0; c < m_header.size(); ++c) {
        if (m_header[c] == name) return c;
    }
    std::string names;
    for (const auto& h : m_header) names += (names.empty() ? "" : ", ") + quotedForMessage(h);
    throw CsvError("'" + m_path + "' has no column " + quotedForMessage(name) + " (columns: " + names + ")");
}

bool CsvReader::next(std::vector<std::string_view>& fields)
{
    if (!nextLine()) return false;
    splitCsvLine(m_line, m_delimiter, fields);
    if (m_trailingDelimiter && fields.size() == m_header.size() + 1 && fields.back().empty()) fields.pop_back();
    if (fields.size() != m_header.size())
        throw CsvError("'" + m_path + "' line " + std::to_string(m_lineNumber) + " has " +
                       std::to_string(fields.size()) + " fields, the header has " + std::to_string(m_header.size()));
    return true;
}

double CsvReader::number(std::string_view cell, std::size_t column) const
{
    double value = 0.0;
    const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (error == std::errc::result_out_of_range) throw cellError(cell, column, "is out of a number's range");
    if (cell.empty() || error != std::errc() || end != cell.data() + cell.size())
        throw cellError(cell, column, "is not a number");
    if (std::isinf(value)) throw cellError(cell, column, "is not a finite number");
    return value;
}

CsvError CsvReader::cellError(std::string_view cell, std::size_t column, const std::string& why) const
{
    return CsvError("'" + m_path + "' line " + std::to_string(m_lineNumber) + ", column " +
                    quotedForMessage(m_header[column]) + ": " + quotedForMessage(cell) + " " + why);
}

}  // namespace tactiscope::core::io
