// Reading a CSV file row by row, for files too large to hold (at a few
// hundred MB/s: one large read buffer, views, std::from_chars): the header,
// then the fields of each data row with its line number. The delimiter is
// the header's (comma, semicolon or tab, as other DAQ programs write);
// lines end in LF, CRLF or CR alone (old Mac programs); a UTF-8 byte-order
// mark is skipped; a delimiter ending every line (some loggers write one)
// adds no column; blank lines and lines starting with '#' are skipped.
// Errors name the file, the line and the column, and quote at most 80
// characters of a cell, so a user can fix the file.
#pragma once

#include "core/io/CsvColumns.h"

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::io {

class CsvReader {
public:
    // Opens the file and reads the header. Throws CsvError.
    explicit CsvReader(const std::string& path);

    const std::vector<std::string>& header() const { return m_header; }
    // The index of a header name; throws CsvError naming the columns there are.
    std::size_t column(const std::string& name) const;
    // The next data row, its fields trimmed of spaces and quotes; false at
    // the end. Throws CsvError for a row with a different number of fields.
    bool next(std::vector<std::string_view>& fields);
    std::size_t lineNumber() const { return m_lineNumber; }
    std::uint64_t bytesRead() const { return m_bytesRead; }  // for progress
    const std::string& path() const { return m_path; }

    // A cell as a number (std::from_chars: no locale); "nan" is a missing
    // value, an infinity is refused. Throws CsvError naming the line and
    // the column.
    double number(std::string_view cell, std::size_t column) const;
    // The error for a cell of the current line: "'P' line L, column 'C':
    // 'cell' why".
    CsvError cellError(std::string_view cell, std::size_t column, const std::string& why) const;

private:
    bool nextLine();
    bool nextRawLine(std::string_view& line);
    void readHeader();

    std::string m_path;
    std::ifstream m_file;
    // A large buffer read straight from the file; lines are views into it,
    // so a row costs no allocation and no copy.
    std::vector<char> m_buffer;
    std::size_t m_position = 0;  // start of the unread text
    std::size_t m_filled = 0;    // end of the text read
    bool m_endOfFile = false;
    std::string_view m_line;
    std::size_t m_lineNumber = 0;
    std::uint64_t m_bytesRead = 0;
    char m_delimiter = ',';
    char m_lineEnd = '\n';
    bool m_trailingDelimiter = false;  // every line ends in the delimiter
    std::vector<std::string> m_header;
};

// A column header's name and unit: "force [N]" and "force (N)" → force, N;
// "a" → a and no unit.
struct ColumnHeader {
    std::string name;
    std::string unit;
};
ColumnHeader splitColumnHeader(const std::string& header);

// A file's text quoted for a message: at most 80 characters, so an error on
// a 200 MB cell is one line, not the cell.
std::string quotedForMessage(std::string_view text);

// Splits `line` at `delimiter` into trimmed fields (views into the line).
void splitCsvLine(std::string_view line, char delimiter, std::vector<std::string_view>& fields);

}  // namespace tactiscope::core::io
