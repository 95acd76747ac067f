// A board that changes what it prints mid-recording (issue 53): its new
// layout continues the session. Through a real pseudo-terminal and
// `record`, a board printing "a:n b:-n" renames b to c and then begins to
// print d: the session holds a, b, c and d, each value where the board
// printed it and holes elsewhere (c and d before their first value, b
// after its last), and each change as a note at the sample it began at.
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextBoard.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <thread>

using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::TextBoard;
namespace core = tactiscope::core;
namespace storage = tactiscope::core::storage;

namespace {

// A board printing "a:n" at 100 Hz that begins to print d kDAfter lines
// after line `fires`, a second from when it starts, recorded for 3.5 s with
// `options(fires)` (a trigger at that line): what `record` said, `fires`
// and the store.
constexpr std::uint64_t kDAfter = 80;
struct BoardThatAddsD {
    tactiscope::testing::CliResult result;
    std::uint64_t fires = 0;
    QString db;
};
BoardThatAddsD recordBoardThatAddsD(const QTemporaryDir& dir,
                                    const std::function<QStringList(std::uint64_t fires)>& options)
{
    std::atomic<std::uint64_t> added = std::numeric_limits<std::uint64_t>::max();
    const auto line = [&](std::uint64_t n) {
        std::string text = "a:" + std::to_string(n);
        if (n >= added) text += " d:" + std::to_string(n % 7);
        return text + "\r\n";
    };
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoard board(link, {100.0, line, 2, 1e-3, true});
    EXPECT_TRUE(board.ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    BoardThatAddsD recorded;
    recorded.fires = board.printed() + 100;
    added = recorded.fires + kDAfter;
    recorded.db = dir.filePath(QStringLiteral("board.tactiscope"));
    recorded.result = runCli(QStringList{"record", "--port", QString::fromStdString(link), "--protocol", "text",
                                         "--rate", "100", "--seconds", "3.5", "--db", recorded.db} +
                             options(recorded.fires));
    return recorded;
}

}  // namespace

TEST(TextBoardLayoutCli, ABoardThatRenamesAChannelAndAddsOneContinuesTheSessionWithEveryValue)
{
    constexpr double kRate_hz = 100.0;
    // Where the board renames b to c, and where it adds d: set once it prints.
    std::atomic<std::uint64_t> renamed = std::numeric_limits<std::uint64_t>::max();
    std::atomic<std::uint64_t> added = std::numeric_limits<std::uint64_t>::max();
    const auto line = [&](std::uint64_t n) {
        const std::string a = "a:" + std::to_string(n);
        if (n < renamed) return a + " b:-" + std::to_string(n) + "\r\n";
        const std::string c = " c:" + std::to_string(0.25 * static_cast<double>(n));
        if (n < added) return a + c + "\r\n";
        return a + c + " d:" + std::to_string(n % 7) + "\r\n";
    };
    QTemporaryDir dir;
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoard board(link, {kRate_hz, line, 2, 1e-3, true});
    ASSERT_TRUE(board.ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    // The recording begins about half a second from here and lasts 3 s.
    renamed = board.printed() + 150;
    added = renamed + 100;
    const QString db = dir.filePath(QStringLiteral("board.tactiscope"));
    const auto result = runCli({"record", "--port", QString::fromStdString(link), "--protocol", "text", "--rate", "100",
                                "--seconds", "3", "--db", db});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    const auto id = sessionIdIn(result.out);
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 4u) << result.out.toStdString();
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(channels[c].descriptor.name, std::string(1, "abcd"[c]));
    const std::uint64_t count = store.sampleCount(id);
    EXPECT_TRUE(store.gaps(id).empty());
    std::vector<std::vector<double>> values;
    for (std::size_t c = 0; c < 4; ++c) values.push_back(store.readChannel(id, c, 0, count));
    const auto first = static_cast<std::uint64_t>(values[0][0]);
    ASSERT_LT(first, renamed.load()) << "the recording began after the rename";
    ASSERT_GT(first + count, added.load() + 10) << "the recording ended before d was added";
    for (std::uint64_t s = 0; s < count; ++s) {
        const std::uint64_t n = first + s;
        SCOPED_TRACE("line " + std::to_string(n));
        ASSERT_EQ(values[0][s], static_cast<double>(n));  // consecutive lines, every one
        if (n < renamed) {
            EXPECT_EQ(values[1][s], -static_cast<double>(n));
            EXPECT_TRUE(std::isnan(values[2][s]));
        } else {
            EXPECT_TRUE(std::isnan(values[1][s]));
            EXPECT_FLOAT_EQ(static_cast<float>(values[2][s]), static_cast<float>(0.25 * static_cast<double>(n)));
        }
        if (n < added)
            EXPECT_TRUE(std::isnan(values[3][s]));
        else
            EXPECT_EQ(values[3][s], static_cast<double>(n % 7));
    }
    // Each change a note (no alarm) at the sample it began at.
    std::vector<storage::SessionEvent> notes;
    for (const auto& event : store.events(id))
        if (event.note.starts_with("the board's channels changed")) notes.push_back(event);
    ASSERT_EQ(notes.size(), 2u);
    EXPECT_EQ(notes[0].kind, core::EventKind::Marker);
    EXPECT_NEAR(notes[0].start_s, static_cast<double>(renamed - first) / kRate_hz, 1e-9);
    EXPECT_EQ(notes[0].note, "the board's channels changed: c appeared (holes before the first value); b is no longer "
                             "printed (holes from here)");
    EXPECT_NEAR(notes[1].start_s, static_cast<double>(added - first) / kRate_hz, 1e-9);
    EXPECT_EQ(notes[1].note, "the board's channels changed: d appeared (holes before the first value)");
}

// The same seam in a triggered recording: the session the trigger cut
// gains the channel its board began to print, with the note.
TEST(TextBoardLayoutCli, ATriggeredSessionGainsTheChannelItsBoardBeganToPrint)
{
    QTemporaryDir dir;
    const auto [result, fires, db] = recordBoardThatAddsD(dir, [](std::uint64_t at) {
        return QStringList{"--trigger", QStringLiteral("a>%1").arg(static_cast<double>(at) - 0.5)};
    });
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u) << result.out.toStdString();
    const auto id = sessions.front().id;
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[1].descriptor.name, "d");
    const std::uint64_t count = store.sampleCount(id);
    const auto a = store.readChannel(id, 0, 0, count), d = store.readChannel(id, 1, 0, count);
    EXPECT_EQ(static_cast<std::uint64_t>(a[0]), fires);
    for (std::uint64_t s = 0; s < count; ++s) {
        const auto n = static_cast<std::uint64_t>(a[s]);
        ASSERT_EQ(n, fires + s);
        if (n < fires + kDAfter)
            EXPECT_TRUE(std::isnan(d[s])) << n;
        else
            EXPECT_EQ(d[s], static_cast<double>(n % 7)) << n;
    }
    const auto events = store.events(id);
    EXPECT_TRUE(std::ranges::any_of(events, [](const auto& e) {
        return e.note == "the board's channels changed: d appeared (holes before the first value)";
    }));
}

// Issue 57's seams on a text board: a session triggered by a math channel
// (twice = 2·a) with a low-pass on a, whose board begins to print d
// mid-session. The trigger fires on the math channel's first value over
// its level (over a as filtered, so the filter's delay later), the session
// keeps the setup it was recorded with (a filtered, the math channel), the
// operator is told d came after it (recorded as it came, not filtered),
// and the export's math column is its expression over a as filtered,
// which the math channel reads.
TEST(TextBoardLayoutCli, ASessionTriggeredByAMathChannelKeepsItsSetupAndSaysALateChannelIsNotFiltered)
{
    QTemporaryDir dir;
    const auto [result, fires, db] = recordBoardThatAddsD(dir, [](std::uint64_t at) {
        return QStringList{"--lowpass",        "10",
                           "--filter-channel", "a",
                           "--math",           "twice[]=2 * a",
                           "--trigger",        QStringLiteral("twice>%1").arg(2.0 * static_cast<double>(at) - 1.0)};
    });
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_TRUE(result.err.contains(
        QStringLiteral("d came after the filters and math channels were set: it is recorded as it came, not filtered")))
        << result.err.toStdString();
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u) << result.out.toStdString();
    const auto id = sessions.front().id;
    // The trigger reads the math channel, over a as filtered: a ramp through
    // the low-pass lags by its delay at DC, 2.613 / ω_c for a 4th-order
    // Butterworth, ω_c prewarped to 2·100·tan(π·10/100) = 64.98 rad/s: 4.02
    // samples. So 2·(n − 4.02) first exceeds 2·fires − 1 at n = fires + 4.
    EXPECT_EQ(static_cast<std::uint64_t>(store.readChannel(id, 0, 0, 1).front()), fires + 4);
    EXPECT_NE(sessions.front().metadata.signalSetup.find("\"channel\":\"a\""), std::string::npos)
        << sessions.front().metadata.signalSetup;
    EXPECT_NE(sessions.front().metadata.signalSetup.find("twice[]=2 * a"), std::string::npos);

    const QString csv = dir.filePath(QStringLiteral("x.csv"));
    ASSERT_EQ(
        runCli({"sessions", "--db", db, "export", QString::number(id), "--format", "csv", "--output", csv}).exitCode,
        0);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(QString::fromUtf8(file.readLine()).trimmed(), QStringLiteral("t [s],a,d,a.filtered,twice"));
    int rows = 0;
    while (!file.atEnd()) {
        const QStringList cells = QString::fromUtf8(file.readLine()).trimmed().split(QLatin1Char(','));
        ASSERT_EQ(cells.size(), 5);
        // Over a as filtered (a math channel reads a filtered channel so), in
        // every digit: both columns are written to read back exactly.
        EXPECT_EQ(cells[4].toDouble(), 2.0 * cells[3].toDouble()) << rows;
        ++rows;
    }
    EXPECT_GT(rows, 150);
}

// A rename while the board's rate is timed, before the recording: the
// session holds b (its channels are the stream's) as holes only, and both
// the notice and the holes note say so, and the session keeps why at its
// start. Before, the notice did not say it came before the recording, the
// note counted no hole in b, and the session did not say why b was empty.
TEST(TextBoardLayoutCli, ARenameBeforeTheRecordingIsKeptAtItsStartAndItsChannelCountedAsHoles)
{
    std::atomic<std::uint64_t> renamed = std::numeric_limits<std::uint64_t>::max();
    const auto line = [&](std::uint64_t n) {
        return "a:" + std::to_string(n) + (n < renamed ? " b:" : " c:") + std::to_string(n % 5) + "\r\n";
    };
    QTemporaryDir dir;
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoard board(link, {100.0, line, 2, 2e-3, true});
    ASSERT_TRUE(board.ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    // A second from here: the port is open by then, and the lines' rate
    // takes seconds more to settle.
    renamed = board.printed() + 100;
    const QString db = dir.filePath(QStringLiteral("board.tactiscope"));
    const auto result =
        runCli({"record", "--port", QString::fromStdString(link), "--protocol", "text", "--seconds", "1", "--db", db});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    const auto id = sessionIdIn(result.out);
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 3u) << result.out.toStdString();
    const std::uint64_t count = store.sampleCount(id);
    const auto a = store.readChannel(id, 0, 0, count), b = store.readChannel(id, 1, 0, count);
    ASSERT_GT(a[0], static_cast<double>(renamed.load())) << "the recording began before the rename";
    EXPECT_TRUE(std::ranges::all_of(b, [](double v) { return std::isnan(v); }));
    const QString err = result.err;
    EXPECT_TRUE(err.contains(QStringLiteral("the board's channels changed: c appeared (holes before the first "
                                            "value); b is no longer printed (holes from here) (before the recording "
                                            "began, so not in it)")))
        << err.toStdString();
    EXPECT_TRUE(err.contains(QStringLiteral(": %1 in b").arg(count))) << err.toStdString();
    const auto events = store.events(id);
    const auto kept = std::ranges::find_if(events, [](const auto& e) {
        return e.note == "before this recording, the board's channels changed: c appeared (holes before the first "
                         "value); b is no longer printed (holes from here)";
    });
    ASSERT_NE(kept, events.end());
    EXPECT_EQ(kept->start_s, 0.0);
    for (const auto& event : events) EXPECT_FALSE(event.note.starts_with("the board's channels")) << event.note;
}
