// A maker's own board through `record --protocol text` (issue 53), on real
// pseudo-terminals with a board that prints with a board's timing
// (support/TextBoard.h): its time is measured, not invented (10 lines a
// second for 20 s are 20 s; 500 a second are timed to 0.05 %), what it
// printed before the port was opened is not recorded, and every dialect
// makers print (the Arduino IDE's Serial Plotter's cases, Teleplot,
// NAME=VALUE, a leading '+', long lines, units in labels, the board's own
// clock) is recorded with its channels' names and every value.
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextBoard.h"

#include "core/storage/SessionStore.h"

#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::TextBoard;
using tactiscope::testing::TextBoardOptions;
namespace storage = tactiscope::core::storage;

namespace {

// What a board prints, and what a recording of it must hold: channel c of
// line n is value(c, n).
struct Dialect {
    std::string what;
    std::function<std::string(std::uint64_t)> line;
    std::vector<std::string> names;
    std::function<double(std::size_t, std::uint64_t)> value;
    std::vector<std::string> units = {};  // empty: none expected
    std::vector<double> toStored = {};    // each channel's factor to its SI unit; empty: 1
    QStringList record = {"--rate", "100"};
    // Teleplot's lines are independent: opened between two of one instant,
    // the port pairs each with the next instant's (docs/protocol.md).
    bool pairedInPrintOrder = false;
};

double standard(std::size_t c, std::uint64_t n)
{
    const auto x = static_cast<double>(n);
    return c == 0 ? x : c == 1 ? -x : x * 0.25;
}

// Records each dialect from its own board at once (one `record` each, for
// `seconds`), then checks each session: the channels' names (and units),
// and that its samples are consecutive lines of the board, value by value.
void recordsEveryValue(const std::vector<Dialect>& dialects, double seconds = 1.0)
{
    QTemporaryDir dir;
    std::vector<std::unique_ptr<TextBoard>> boards;
    std::vector<std::unique_ptr<QProcess>> records;
    for (std::size_t d = 0; d < dialects.size(); ++d) {
        const std::string link = dir.filePath(QStringLiteral("board-%1").arg(d)).toStdString();
        boards.push_back(std::make_unique<TextBoard>(link, TextBoardOptions{100.0, dialects[d].line, 3, 2e-3, true}));
        ASSERT_TRUE(boards.back()->ok());
        records.push_back(std::make_unique<QProcess>());
        records.back()->start(QStringLiteral(TACTISCOPE_CLI),
                              QStringList{"record", "--port", QString::fromStdString(link), "--protocol", "text",
                                          "--seconds", QString::number(seconds), "--db",
                                          dir.filePath(QStringLiteral("board-%1.tactiscope").arg(d))} +
                                  dialects[d].record);
    }
    for (std::size_t d = 0; d < dialects.size(); ++d) {
        const Dialect& dialect = dialects[d];
        SCOPED_TRACE(dialect.what);
        QProcess& record = *records[d];
        ASSERT_TRUE(record.waitForFinished(60000));
        const QString out = QString::fromUtf8(record.readAllStandardOutput());
        ASSERT_EQ(record.exitCode(), 0) << QString::fromUtf8(record.readAllStandardError()).toStdString();
        const auto id = sessionIdIn(out);
        ASSERT_GT(id, 0) << out.toStdString();
        storage::SessionStore store(dir.filePath(QStringLiteral("board-%1.tactiscope").arg(d)).toStdString(),
                                    storage::Database::Access::ReadOnly);
        const auto channels = store.channels(id);
        ASSERT_EQ(channels.size(), dialect.names.size());
        for (std::size_t c = 0; c < channels.size(); ++c) {
            EXPECT_EQ(channels[c].descriptor.name, dialect.names[c]);
            if (!dialect.units.empty()) {
                EXPECT_EQ(channels[c].descriptor.unit, dialect.units[c]) << channels[c].descriptor.name;
            }
        }
        EXPECT_TRUE(store.gaps(id).empty());
        // A board that stamps its lines is timed by its stamps: exactly.
        if (dialect.record.isEmpty()) {
            EXPECT_NEAR(channels[0].sampleRate_hz, 100.0, 1e-9);
        }
        const std::uint64_t count = store.sampleCount(id);
        ASSERT_GT(count, static_cast<std::uint64_t>(50.0 * seconds));
        // The first sample is the board's line n0; every one after, the next line.
        const auto factor = [&](std::size_t c) { return dialect.toStored.empty() ? 1.0 : dialect.toStored[c]; };
        const auto first = store.readChannel(id, 0, 0, count);
        const auto n0 = static_cast<std::uint64_t>(std::llround(first[0] / factor(0)));
        const auto stored = [&](std::size_t c, std::uint64_t n) {
            return static_cast<double>(static_cast<float>(dialect.value(c, n) * factor(c)));
        };
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const auto values = c == 0 ? first : store.readChannel(id, c, 0, count);
            std::uint64_t nc = n0;
            if (dialect.pairedInPrintOrder && values[0] != stored(c, nc))
                nc = values[0] == stored(c, n0 + 1) ? n0 + 1 : n0 - 1;
            for (std::uint64_t i = 0; i < count; ++i)
                ASSERT_EQ(values[i], stored(c, nc + i)) << channels[c].descriptor.name << ", sample " << i;
        }
    }
}

}  // namespace

// The Serial Plotter's cases: space, tab or comma; LF or CRLF; with a
// trailing delimiter or not; labelled or not; one value or three; the
// lines cut across the board's writes. 48 boards, each recorded.
TEST(TextBoardCli, EveryCaseOfTheArduinoSerialPlotterIsRecordedValueByValue)
{
    std::vector<Dialect> dialects;
    for (const std::string separator : {" ", "\t", ","})
        for (const std::string end : {"\n", "\r\n"})
            for (const bool trailing : {false, true})
                for (const bool labelled : {false, true})
                    for (const std::size_t fields : {std::size_t{1}, std::size_t{3}}) {
                        Dialect dialect;
                        dialect.what = "separator '" + separator + "', end " + (end.size() == 1 ? "LF" : "CRLF") +
                                       (trailing ? ", trailing" : "") + (labelled ? ", labelled" : "") + ", " +
                                       std::to_string(fields) + " values";
                        const std::vector<std::string> labels{"x", "y", "z"};
                        for (std::size_t c = 0; c < fields; ++c)
                            dialect.names.push_back(labelled ? labels[c] : "ch" + std::to_string(c + 1));
                        dialect.line = [=](std::uint64_t n) {
                            std::string text;
                            for (std::size_t c = 0; c < fields; ++c) {
                                if (c > 0) text += separator;
                                if (labelled) text += labels[c] + ":";
                                char number[32];
                                std::snprintf(number, sizeof number, "%g", standard(c, n));
                                text += number;
                            }
                            return text + (trailing ? separator : "") + end;
                        };
                        dialect.value = standard;
                        dialects.push_back(std::move(dialect));
                    }
    ASSERT_EQ(dialects.size(), 48u);
    for (std::size_t batch = 0; batch < dialects.size(); batch += 12)
        recordsEveryValue({dialects.begin() + static_cast<std::ptrdiff_t>(batch),
                           dialects.begin() + static_cast<std::ptrdiff_t>(batch + 12)});
}

TEST(TextBoardCli, TheDialectsMakersPrintAreRecordedValueByValue)
{
    const auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", x);
        return std::string(text);
    };
    std::vector<Dialect> dialects;
    // Teleplot, one variable a line, alternating; its units after '§',
    // stored in SI.
    dialects.push_back({"Teleplot",
                        [&](std::uint64_t n) {
                            return ">a:" + number(standard(0, n)) + "\xC2\xA7mN\n>b:" + number(standard(1, n)) +
                                   "\xC2\xA7mN|g\n";
                        },
                        {"a", "b"},
                        standard,
                        {"N", "N"},
                        {1e-3, 1e-3},
                        {"--rate", "100"},
                        true});
    // Teleplot with its timestamps (ms): the board's clock times it.
    dialects.push_back({"Teleplot timestamped",
                        [&](std::uint64_t n) {
                            const std::string at = std::to_string(1700000000000 + n * 10);
                            return ">temp:" + at + ":" + number(standard(0, n)) + "\n";
                        },
                        {"temp"},
                        standard,
                        {},
                        {},
                        {}});
    dialects.push_back(
        {"NAME=VALUE, commas",
         [&](std::uint64_t n) { return "a=" + number(standard(0, n)) + ",b=" + number(standard(1, n)) + "\r\n"; },
         {"a", "b"},
         standard});
    dialects.push_back(
        {"NAME=VALUE, spaces",
         [&](std::uint64_t n) { return "a=" + number(standard(0, n)) + " b=" + number(standard(1, n)) + "\n"; },
         {"a", "b"},
         standard});
    dialects.push_back({"%+.2f",
                        [&](std::uint64_t n) {
                            char text[64];
                            std::snprintf(text, sizeof text, "%+.2f,%+.2f,%+.2f\n", standard(0, n), standard(1, n),
                                          standard(2, n));
                            return std::string(text);
                        },
                        {"ch1", "ch2", "ch3"},
                        standard});
    // 200 channels: a line of over 2,000 bytes.
    std::vector<std::string> many;
    for (int c = 0; c < 200; ++c) many.push_back("ch" + std::to_string(c + 1));
    dialects.push_back(
        {"200 channels",
         [&](std::uint64_t n) {
             std::string text;
             for (int c = 0; c < 200; ++c) text += (c ? "," : "") + number(1000.0 * c + static_cast<double>(n));
             return text + "\n";
         },
         many,
         [](std::size_t c, std::uint64_t n) { return 1000.0 * static_cast<double>(c) + static_cast<double>(n); }});
    // Units in the labels (stored in SI), and the board's millis() as its clock.
    dialects.push_back({"units and millis()",
                        [&](std::uint64_t n) {
                            return "millis:" + std::to_string(5000 + n * 10) + " force[mN]:" + number(standard(0, n)) +
                                   " pos[mm]:" + number(standard(1, n)) + "\n";
                        },
                        {"force", "pos"},
                        standard,
                        {"N", "m"},
                        {1e-3, 1e-3},
                        {}});
    for (auto& dialect : dialects) dialect.what += ": " + dialect.line(7);
    recordsEveryValue(dialects, 1.5);
}

namespace {

// A board printing "a:… b:n" at `rate_hz`, in bursts, late by a jitter,
// its writes cut mid-line, recorded for `seconds` after it has printed
// for a second with nobody reading. Returns the session's sample count,
// rate and first line, and how many lines the board had printed before
// `record` was started.
struct TimedBoard {
    std::uint64_t samples = 0;
    double rate_hz = 0.0;
    std::uint64_t firstLine = 0;
    std::uint64_t printedBefore = 0;
};

TimedBoard recordTimedBoard(double rate_hz, std::size_t linesPerBurst, double seconds)
{
    QTemporaryDir dir;
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoard board(link, {rate_hz,
                           [](std::uint64_t n) {
                               return "a:" + std::to_string(std::sin(0.01 * static_cast<double>(n))) +
                                      " b:" + std::to_string(n) + "\r\n";
                           },
                           linesPerBurst, 3e-3, true});
    EXPECT_TRUE(board.ok());
    std::this_thread::sleep_for(std::chrono::seconds(1));
    TimedBoard timed;
    timed.printedBefore = board.printed();
    const QString db = dir.filePath(QStringLiteral("board.tactiscope"));
    const auto result = runCli({"record", "--port", QString::fromStdString(link), "--protocol", "text", "--seconds",
                                QString::number(seconds), "--db", db});
    EXPECT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto id = sessionIdIn(result.out);
    EXPECT_GT(id, 0) << result.out.toStdString();
    if (id <= 0) return timed;
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    timed.samples = store.sampleCount(id);
    timed.rate_hz = store.channels(id)[0].sampleRate_hz;
    timed.firstLine = static_cast<std::uint64_t>(std::llround(store.readChannel(id, 1, 0, 1)[0]));
    EXPECT_TRUE(store.gaps(id).empty());
    return timed;
}

}  // namespace

// Before, a 10 Hz board was timed at 13.33 Hz and 20 s were stored as 15.
TEST(TextBoardCli, TenLinesASecondForTwentySecondsAreStoredAsTwentySeconds)
{
    const auto board = recordTimedBoard(10.0, 1, 20.0);
    EXPECT_NEAR(static_cast<double>(board.samples) / board.rate_hz, 20.0, 0.1 + 1e-9);
    EXPECT_NEAR(board.rate_hz, 10.0, 0.01);
    // Neither what waited in the port nor the lines held while the rate
    // was timed (2.5 s) are in the session.
    EXPECT_GT(board.firstLine, board.printedBefore + 20);
}

// Before, a 500 Hz board was timed at 502.3–506.6 Hz, and a 10 s recording
// held 6,010 samples.
TEST(TextBoardCli, FiveHundredLinesASecondAreTimedWithinFiveHundredthsOfAPercent)
{
    const auto board = recordTimedBoard(500.0, 8, 10.0);
    EXPECT_LT(std::abs(board.rate_hz / 500.0 - 1.0), 5e-4) << board.rate_hz;
    EXPECT_NEAR(static_cast<double>(board.samples), 5000.0, 50.0);
    EXPECT_GT(board.firstLine, board.printedBefore + 1000);
}

namespace {

// A board nobody read for a while: its port filled, its writes waited
// (as Serial.write does on a native USB port), and once the port is
// opened it prints, as fast as its link takes them, the lines its schedule
// says are due, far faster than its rate and far longer than the port's
// backlog is read away for. Unread for `unread_s`, then recorded for 3 s
// with `options` given.
struct CaughtUp {
    std::uint64_t dueAtStart = 0;
    std::uint64_t firstLine = 0;
    std::uint64_t samples = 0;
    double rate_hz = 0.0;
};

CaughtUp recordABoardThatCatchesUp(double rate_hz, double unread_s, const QStringList& options)
{
    QTemporaryDir dir;
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoardOptions printing{rate_hz, [](std::uint64_t n) {
                                  // 16 channels, 200 bytes: the port fills in under a second.
                                  std::string line = "a:" + std::to_string(std::sin(0.01 * static_cast<double>(n))) +
                                                     " b:" + std::to_string(n);
                                  for (int c = 0; c < 14; ++c) line += " c" + std::to_string(c) + ":0.000000";
                                  return line + "\n";
                              }};
    printing.longestWait_s = 60.0;
    printing.linkBytesPerSecond = 1e6;
    TextBoard board(link, printing);
    EXPECT_TRUE(board.ok());
    std::this_thread::sleep_for(std::chrono::duration<double>(unread_s));
    CaughtUp caught;
    caught.dueAtStart = board.due();
    EXPECT_GT(caught.dueAtStart, board.printed() + 1000) << "the board was not held up";
    const QString db = dir.filePath(QStringLiteral("board.tactiscope"));
    const auto result = runCli(QStringList{"record", "--port", QString::fromStdString(link), "--protocol", "text",
                                           "--seconds", "3", "--db", db} +
                               options);
    EXPECT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto id = sessionIdIn(result.out);
    EXPECT_GT(id, 0) << result.out.toStdString();
    if (id <= 0) return caught;
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    caught.firstLine = static_cast<std::uint64_t>(std::llround(store.readChannel(id, 1, 0, 1)[0]));
    caught.samples = store.sampleCount(id);
    caught.rate_hz = store.channels(id)[0].sampleRate_hz;
    return caught;
}

}  // namespace

// The last lines of a catch-up come as fast as the link carries them and
// as late as a loaded host reads them: the last tenth of a second of it
// (50 lines at 500 Hz) cannot be told from lines on time. (Once, under a
// full suite's load, 21 lines, 42 ms, were recorded.)
constexpr std::uint64_t kLinesWithinLatency = 50;

// Before, with --rate given, the catch-up was recorded as the session's
// first seconds (a 3 s recording after 35 s unread held 17 s); then, once
// its lines spanned more than 10 s, as the start the recording had waited
// too long for (a 2 s recording after a minute unread held 21.5 s).
TEST(TextBoardCli, WhatABoardCatchesUpOnOnceThePortIsOpenedIsNotRecorded)
{
    const auto given = recordABoardThatCatchesUp(500.0, 12.0, {"--rate", "500"});
    EXPECT_GE(given.firstLine + kLinesWithinLatency, given.dueAtStart);
    // Three seconds at most (the catch-up alone is over 11 s of lines), less
    // what a slow reader (a sanitizer's, sharing its cores) had not read
    // by the stop.
    EXPECT_LE(given.samples, 1550u);
    EXPECT_GE(given.samples, 1200u);
}

// Timed from its lines, the catch-up neither sways the rate nor is recorded.
TEST(TextBoardCli, ABoardThatCatchesUpIsTimedByTheLinesThatCameOnTime)
{
    const auto timed = recordABoardThatCatchesUp(500.0, 5.0, {});
    EXPECT_LT(std::abs(timed.rate_hz / 500.0 - 1.0), 1e-3) << timed.rate_hz;
    EXPECT_GE(timed.firstLine + kLinesWithinLatency, timed.dueAtStart);
    EXPECT_LE(timed.samples, 1550u);
    EXPECT_GE(timed.samples, 1200u);
}
