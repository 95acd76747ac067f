// The CSV reader on files other programs write, each a weak spot that once
// misled (issue 19): a UTF-8 byte-order mark was part of the first column's
// name; CR-only line endings made the whole file one garbled header; a
// delimiter ending every line added a nameless all-NaN channel; duplicate
// column names were accepted; "inf" and 1e400 passed as numbers; an error
// on a huge cell echoed all of it.
#include "core/io/CsvReader.h"
#include "core/io/CsvColumns.h"
#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using tactiscope::core::io::CsvError;
using tactiscope::core::io::CsvReader;

namespace {

class CsvReaderTest : public tactiscope::testing::TempDirectoryTest {
protected:
    std::string write(const std::string& bytes)
    {
        const std::string path = file("in.csv");
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    // The error reading every row and cell of the file gives, or "" if none.
    std::string errorReading(const std::string& bytes)
    {
        try {
            CsvReader reader(write(bytes));
            std::vector<std::string_view> fields;
            while (reader.next(fields))
                for (std::size_t c = 0; c < fields.size(); ++c) (void)reader.number(fields[c], c);
        } catch (const CsvError& e) {
            return e.what();
        }
        return {};
    }
};

}  // namespace

TEST_F(CsvReaderTest, AByteOrderMarkIsNotPartOfTheFirstName)
{
    CsvReader reader(write("\xEF\xBB\xBFt,a\n0,1\n"));
    EXPECT_EQ(reader.header(), (std::vector<std::string>{"t", "a"}));
}

TEST_F(CsvReaderTest, CarriageReturnsAloneEndLines)
{
    CsvReader reader(write("t,a\r0,1.5\r0.1,2.5\r"));
    EXPECT_EQ(reader.header(), (std::vector<std::string>{"t", "a"}));
    std::vector<std::string_view> fields;
    ASSERT_TRUE(reader.next(fields));
    EXPECT_EQ(reader.number(fields[1], 1), 1.5);
    ASSERT_TRUE(reader.next(fields));
    EXPECT_EQ(reader.lineNumber(), 3u);
    EXPECT_EQ(reader.number(fields[1], 1), 2.5);
    EXPECT_FALSE(reader.next(fields));
}

TEST_F(CsvReaderTest, LinesAcrossTheReadBufferAndLongerThanItReadWhole)
{
    // 3 MB of rows (the reader's buffer is 1 MB, so rows straddle its
    // ends), one row with a 2.5 MB note, and a last line without an end.
    std::string text = "t;a;note\r\n";
    std::vector<double> expected;
    for (int i = 0; i < 100000; ++i) {
        const double value = 0.5 * i + 0.25;
        expected.push_back(value);
        text += std::to_string(i) + ";" + std::to_string(value) + ";row number " + std::to_string(i) + "\r\n";
        if (i == 50000) text += "50000.5;7;" + std::string(2'500'000, 'x') + "\r\n";
    }
    text += "100000;9;last";
    CsvReader reader(write(text));
    std::vector<std::string_view> fields;
    std::size_t row = 0;
    while (reader.next(fields)) {
        if (row == 50001) {
            EXPECT_EQ(fields[2].size(), 2'500'000u);
        } else if (row == 100001) {
            EXPECT_EQ(fields[2], "last");
        } else {
            const std::size_t i = row > 50001 ? row - 1 : row;
            ASSERT_EQ(reader.number(fields[1], 1), expected[i]) << "row " << row;
            ASSERT_EQ(fields[2], "row number " + std::to_string(i));
        }
        ++row;
    }
    EXPECT_EQ(row, 100002u);
    EXPECT_EQ(reader.lineNumber(), 100003u);
}

TEST_F(CsvReaderTest, ColumnsReadInBlocksAreTheWholeColumns)
{
    std::string text = "t [s],a [strain]\n";
    for (int i = 0; i < 1000; ++i) text += std::to_string(i) + "," + std::to_string(i * i) + "\n";
    const std::string path = write(text);
    tactiscope::core::io::CsvColumnReader reader(path, {"a", "t"});
    std::vector<std::vector<double>> block;
    std::vector<std::size_t> lines;
    std::size_t rows = 0;
    while (const std::size_t n = reader.read(300, block, lines)) {
        ASSERT_EQ(block[0].size(), n);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(block[1][i], static_cast<double>(rows + i));
            EXPECT_EQ(block[0][i], static_cast<double>((rows + i) * (rows + i)));
            EXPECT_EQ(lines[i], rows + i + 2);
        }
        rows += n;
    }
    EXPECT_EQ(rows, 1000u);
}

TEST_F(CsvReaderTest, WindowsLineEndingsStillWork)
{
    CsvReader reader(write("t,a\r\n0,1.5\r\n"));
    EXPECT_EQ(reader.header(), (std::vector<std::string>{"t", "a"}));
    std::vector<std::string_view> fields;
    ASSERT_TRUE(reader.next(fields));
    EXPECT_EQ(fields[1], "1.5");
}

TEST_F(CsvReaderTest, ADelimiterEndingEveryLineAddsNoColumn)
{
    CsvReader reader(write("t,a,b,\n0,1,2,\n0.1,3,4\n"));
    EXPECT_EQ(reader.header(), (std::vector<std::string>{"t", "a", "b"}));
    std::vector<std::string_view> fields;
    ASSERT_TRUE(reader.next(fields));
    EXPECT_EQ(fields.size(), 3u);
    ASSERT_TRUE(reader.next(fields));  // without the trailing delimiter too
    EXPECT_EQ(fields[2], "4");
}

TEST_F(CsvReaderTest, AHeaderWithANamelessOrARepeatedColumnIsRefused)
{
    EXPECT_NE(errorReading("t,,b\n0,1,2\n").find("column 2 of the header has no name"), std::string::npos);
    EXPECT_NE(errorReading("t,a,b,a\n0,1,2,3\n").find("the header names 'a' twice (columns 2 and 4)"),
              std::string::npos);
}

TEST_F(CsvReaderTest, InfinityAndOverflowAreRefusedNamingTheCell)
{
    EXPECT_NE(errorReading("t,a\n0,1\n1,inf\n").find("line 3, column 'a': 'inf' is not a finite number"),
              std::string::npos);
    EXPECT_NE(errorReading("t,a\n0,-1e400\n").find("line 2, column 'a': '-1e400' is out of a number's range"),
              std::string::npos);
    // "nan" stays what it was: a sample without a value.
    EXPECT_EQ(errorReading("t,a\n0,nan\n"), "");
}

TEST_F(CsvReaderTest, AnErrorOnAHugeCellQuotesEightyCharacters)
{
    const std::string cell(2'000'000, 'x');
    const std::string error = errorReading("t,a\n0," + cell + "\n");
    EXPECT_NE(error.find("'" + std::string(80, 'x') + "…' (2000000 characters) is not a number"), std::string::npos)
        << error.substr(0, 300);
    EXPECT_LT(error.size(), 300u);
}

TEST_F(CsvReaderTest, AColumnIsFoundUnderItsSIUnitAndRefusedUnderAnother)
{
    // The simulator and the exports write units into their headers; the
    // commands that want "t" and "a" read them there, in SI only.
    const auto columns = tactiscope::core::io::readCsvColumns(
        write("t [s],a [strain],b\n0,1e-6,2e-6\n0.002,3e-6,4e-6\n"), {"t", "a", "b"});
    ASSERT_EQ(columns.rowCount(), 2u);
    EXPECT_EQ(columns.columns[0][1], 0.002);
    EXPECT_EQ(columns.columns[1][1], 3e-6);
    try {
        tactiscope::core::io::readCsvColumns(write("t [ms],a\n0,1\n2,3\n"), {"t", "a"});
        ADD_FAILURE() << "a time in ms read as seconds";
    } catch (const CsvError& e) {
        EXPECT_NE(std::string(e.what()).find("the column 't [ms]' is in 'ms'"), std::string::npos) << e.what();
    }
}
