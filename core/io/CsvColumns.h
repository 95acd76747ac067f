// Reading numeric columns from a CSV file with a header row, for data that
// other DAQ programs and the simulator write. Errors name the file, the line
// and the column, so a user can fix the file.
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::io {

// Thrown for anything wrong with the file; what() is one line for the user.
class CsvError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CsvColumns {
    std::vector<std::string> header;           // all column names, in file order
    std::vector<std::vector<double>> columns;  // the wanted columns, in the order asked for
    std::vector<std::size_t> lines;            // file line number of each row (1 = header)

    std::size_t rowCount() const { return lines.size(); }
};

// Reads the columns named in `wanted` (header names are trimmed of spaces
// and double quotes); "a" is also found as "a [strain]" or "t" as "t [s]":
// a header that names an SI unit (s, m, N, F, strain, count) reads as
// it is, one in another unit ("t [ms]") is refused. Blank lines are skipped. Every cell of a wanted column
// must be a finite number. Throws CsvError for a missing or unreadable
// file, an empty file, a header without data rows, a missing column, a row
// with a different number of fields, or a bad cell.
CsvColumns readCsvColumns(const std::string& path, const std::vector<std::string>& wanted);

class CsvReader;

// The same columns, a block of rows at a time into buffers the caller
// reuses, for a file read once from start to end (the detector's input):
// memory stays one block whatever the file's size. Same rules and errors
// as readCsvColumns.
class CsvColumnReader {
public:
    CsvColumnReader(const std::string& path, const std::vector<std::string>& wanted);  // throws CsvError
    ~CsvColumnReader();
    CsvColumnReader(const CsvColumnReader&) = delete;
    CsvColumnReader& operator=(const CsvColumnReader&) = delete;

    const std::vector<std::string>& header() const;
    // Up to `maxRows` more rows: columns[w] (one per wanted column) and
    // `lines` (each row's file line number) resized to the rows read; 0 at
    // the end of the file. Throws CsvError.
    std::size_t read(std::size_t maxRows, std::vector<std::vector<double>>& columns, std::vector<std::size_t>& lines);

private:
    std::unique_ptr<CsvReader> m_reader;
    std::vector<std::size_t> m_fields;  // file column of each wanted one
    std::vector<std::string_view> m_row;
};

}  // namespace tactiscope::core::io
