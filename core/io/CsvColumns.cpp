// CSV column reader: CsvReader's rows, the wanted cells kept as numbers.
#include "core/io/CsvColumns.h"

#include "core/io/CsvReader.h"

#include <cmath>

namespace tactiscope::core::io {

CsvColumns readCsvColumns(const std::string& path, const std::vector<std::string>& wanted)
{
    CsvReader reader(path);
    CsvColumns result;
    result.header = reader.header();
    std::vector<std::size_t> wantedField;
    for (const auto& name : wanted) wantedField.push_back(reader.column(name));
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
