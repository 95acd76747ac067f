// CSV column reader: one pass over the file read at once, std::from_chars
// for numbers (locale-independent and fast enough for hours of data).
#include "core/io/CsvColumns.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

namespace tactiscope::core::io {
namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '"')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '"' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// Splits a line at commas into `fields` (views into the line).
void split(std::string_view line, std::vector<std::string_view>& fields)
{
    fields.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
}

std::string readWholeFile(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) throw CsvError("cannot open '" + path + "': " + std::strerror(errno));
    std::ostringstream contents;
    contents << file.rdbuf();
    if (file.bad()) throw CsvError("cannot read '" + path + "'");
    return std::move(contents).str();
}

}  // namespace

CsvColumns readCsvColumns(const std::string& path, const std::vector<std::string>& wanted)
{
    const std::string text = readWholeFile(path);
    CsvColumns result;
    std::vector<std::size_t> wantedField(wanted.size());
    std::vector<std::string_view> fields;
    std::size_t lineNumber = 0;
    bool haveHeader = false;

    std::size_t position = 0;
    while (position < text.size()) {
        std::size_t end = text.find('\n', position);
        if (end == std::string::npos) end = text.size();
        const std::string_view line = std::string_view(text).substr(position, end - position);
        position = end + 1;
        ++lineNumber;
        if (trim(line).empty()) continue;
        split(line, fields);

        if (!haveHeader) {
            haveHeader = true;
            for (auto field : fields) result.header.emplace_back(trim(field));
            for (std::size_t w = 0; w < wanted.size(); ++w) {
                const auto at = std::find(result.header.begin(), result.header.end(), wanted[w]);
                if (at == result.header.end()) {
                    std::string names;
                    for (const auto& name : result.header) names += (names.empty() ? "" : ", ") + name;
                    throw CsvError("'" + path + "' has no column '" + wanted[w] + "' (columns: " + names + ")");
                }
                wantedField[w] = static_cast<std::size_t>(at - result.header.begin());
            }
            result.columns.resize(wanted.size());
            continue;
        }

        if (fields.size() != result.header.size()) {
            throw CsvError("'" + path + "' line " + std::to_string(lineNumber) + " has " +
                           std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(result.header.size()));
        }
        for (std::size_t w = 0; w < wanted.size(); ++w) {
            const std::string_view cell = trim(fields[wantedField[w]]);
            double value = 0.0;
            const auto [parsedTo, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
            if (error != std::errc() || parsedTo != cell.data() + cell.size() || cell.empty() ||
                !std::isfinite(value)) {
                throw CsvError("'" + path + "' line " + std::to_string(lineNumber) + ", column '" + wanted[w] + "': '" +
                               std::string(cell) + "' is not a number");
            }
            result.columns[w].push_back(value);
        }
        result.lines.push_back(lineNumber);
    }
    if (!haveHeader) throw CsvError("'" + path + "' is empty");
    if (result.lines.empty()) throw CsvError("'" + path + "' has a header but no data rows");
    return result;
}

}  // namespace tactiscope::core::io
