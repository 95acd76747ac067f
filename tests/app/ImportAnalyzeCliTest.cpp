// `tactiscope-cli import` and `analyze` on real files: a foreign CSV with a
// millisecond time column and missing rows lands as a session with gaps;
// export → import into another store → export gives the same files to the
// byte (the session's identity, times, status and verdict trail included), and
// the same samples to the bit; importing a session a store already holds
// is refused; analyze finds the events detect finds in the same data; bad
// input gives exit code 2 and one clear line.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <utility>

using namespace tactiscope;
using tactiscope::testing::readBytes;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

namespace {

QJsonObject json(const QString& text)
{
    return QJsonDocument::fromJson(text.toUtf8()).object();
}

}  // namespace

TEST(ImportCli, AForeignCsvWithMillisecondsAndMissingRowsBecomesASessionWithGaps)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("daq.csv");
    // 250 Hz (4 ms), semicolon-separated like a decimal-comma locale's
    // export; rows 3 and 4 are missing; a comment line and a blank cell.
    writeText(csv, "# exported by SomeDAQ 3.1\n"
                   "Time [ms];Force (N);Gap [mm]\n"
                   "1000;0.5;2\n"
                   "1004;0.25;2.5\n"
                   "1008;-0.125;3\n"
                   "1020;1.5;\n"
                   "1024;2;4\n");
    const QString db = dir.filePath("s.tactiscope");
    const auto result = runCli({"import", csv, "--db", db, "--mode", "palpation", "--subject", "phantom-9"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_TRUE(result.out.contains("5 rows of 2 channels at 250 Hz, 2 missing")) << result.out.toStdString();

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = *store.session(1);
    EXPECT_EQ(session.metadata.mode, tactiscope::core::Mode::Palpation);
    EXPECT_EQ(session.metadata.subject, "phantom-9");
    EXPECT_EQ(session.status, tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(session.sampleRate_hz, 250.0);
    EXPECT_EQ(session.sampleCount, 7u);
    const auto channels = store.channels(1);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[0].descriptor, (core::ChannelDescriptor{"Force", "N", core::ChannelKind::Force}));
    // Stored in SI: mm as m.
    EXPECT_EQ(channels[1].descriptor, (core::ChannelDescriptor{"Gap", "m", core::ChannelKind::Position}));
    EXPECT_EQ(store.readChannel(1, 1, 1, 1)[0], static_cast<double>(static_cast<float>(2.5e-3)));
    const auto gaps = store.gaps(1);
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_EQ(gaps[0].firstIndex, 3u);
    EXPECT_EQ(gaps[0].count, 2u);
    const auto force = store.readChannel(1, 0, 0, 7);
    EXPECT_EQ(force[0], 0.5);
    EXPECT_EQ(force[2], -0.125);
    EXPECT_TRUE(std::isnan(force[3]));
    EXPECT_EQ(force[5], 1.5);
    EXPECT_EQ(force[6], 2.0);
    EXPECT_TRUE(std::isnan(store.readChannel(1, 1, 5, 1)[0]));  // the blank cell
}

// Issue 53: a column with no unit is a plain number, unless told.
TEST(ImportCli, BareColumnsStayPlainNumbersUnlessAModeOrTheirUnitsSayOtherwise)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("bench.csv");
    writeText(csv, "t,left,right\n0,1,-1\n0.01,2,-2\n0.02,3,-3\n0.03,4,-4\n");
    const QString db = dir.filePath("s.tactiscope");
    const auto plain = runCli({"import", csv, "--db", db});
    ASSERT_EQ(plain.exitCode, 0) << plain.err.toStdString();
    const auto scan = runCli({"import", csv, "--db", db, "--mode", "panel-scan"});
    ASSERT_EQ(scan.exitCode, 0) << scan.err.toStdString();
    EXPECT_TRUE(scan.out.contains("note: left, right carry no unit: read as strain, which a panel scan reads"))
        << scan.out.toStdString();
    const auto given = runCli({"import", csv, "--db", db, "--units", "left=µε,right=µε"});
    ASSERT_EQ(given.exitCode, 0) << given.err.toStdString();
    const auto unknown = runCli({"import", csv, "--db", db, "--units", "middle=N"});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(unknown.err.contains("--units names 'middle', which is not one of its data columns"))
        << unknown.err.toStdString();

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.session(1)->metadata.mode, core::Mode::General);
    EXPECT_EQ(store.channels(1)[0].descriptor, (core::ChannelDescriptor{"left", "", core::ChannelKind::Other}));
    EXPECT_EQ(store.readChannel(1, 0, 1, 1)[0], 2.0);
    EXPECT_EQ(store.session(2)->metadata.mode, core::Mode::PanelScan);
    EXPECT_EQ(store.channels(2)[0].descriptor.kind, core::ChannelKind::Strain);
    EXPECT_EQ(store.readChannel(2, 0, 1, 1)[0], 2.0);  // as written: the mode's assumption, said
    EXPECT_EQ(store.session(3)->metadata.mode, core::Mode::PanelScan);
    EXPECT_EQ(store.channels(3)[1].descriptor, (core::ChannelDescriptor{"right", "", core::ChannelKind::Strain}));
    EXPECT_EQ(store.readChannel(3, 1, 1, 1)[0], static_cast<double>(static_cast<float>(-2e-6)));
}

// Two columns of one name (a logger's "a [mV]" and "a [V]") cannot both be
// a channel: an export, a math channel and a limit name a channel by its
// name. The file is refused, naming it, and nothing is stored.
TEST(ImportCli, TwoColumnsOfOneNameAreRefused)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("twice.csv");
    writeText(csv, "t,a [mV],a [V]\n0,1,0.001\n0.01,2,0.002\n");
    const QString db = dir.filePath("s.tactiscope");
    const auto refused = runCli({"import", csv, "--db", db});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_TRUE(refused.err.contains("has two columns named 'a'")) << refused.err.toStdString();
    if (QFile::exists(db)) {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        EXPECT_TRUE(store.sessions().empty());
    }
}

// What a board's log holds for no number is a hole in that column alone,
// as from the board live (before, "inf" refused the file).
TEST(ImportCli, ACellThatIsNoNumberIsAHoleInItsColumnAlone)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("board.csv");
    writeText(csv, "t,a,b\n0,1,nan\n0.01,inf,2\n0.02,3,-Inf\n0.03,ovf,4\n0.04,5,\n0.05,6,7\n");
    const QString db = dir.filePath("s.tactiscope");
    const auto imported = runCli({"import", csv, "--db", db});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(store.sampleCount(1), 6u);
    const auto a = store.readChannel(1, 0, 0, 6);
    const auto b = store.readChannel(1, 1, 0, 6);
    const std::vector<bool> aHoles{false, true, false, true, false, false};
    const std::vector<bool> bHoles{true, false, true, false, true, false};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(std::isnan(a[i]), aHoles[i]) << i;
        EXPECT_EQ(std::isnan(b[i]), bHoles[i]) << i;
    }
    EXPECT_EQ(a[5], 6.0);
    EXPECT_EQ(b[5], 7.0);
}

TEST(ImportCli, ExportImportExportIsTheSameFilesAndTheSameBits)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope"), elsewhere = dir.filePath("elsewhere.tactiscope");
    {
        // Values with no short decimal form: the export must carry every bit.
        // The recording was cut short (interrupted, its last 50 samples
        // lost) and judged afterwards: all of that is its identity.
        core::storage::SessionStore store(db.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::Capacitive;
        metadata.subject = "beam-7";
        metadata.operatorName = "Lin";
        const auto id =
            store.beginSession(metadata,
                               std::vector<core::ChannelDescriptor>{{"c", "pF", core::ChannelKind::Capacitance},
                                                                    {"s", "", core::ChannelKind::Strain}},
                               1000.0);
        const auto block = [](std::uint64_t first, std::size_t count) {
            core::SampleBlock b(2, count, static_cast<double>(first) / 1000.0, 1e-3, first);
            for (std::size_t s = 0; s < count; ++s) {
                b.channel(0)[s] = 3.0 + std::sin(static_cast<double>(first + s) * 0.37) / 7.0;
                b.channel(1)[s] = std::exp(-static_cast<double>(first + s) / 300.0) * 1e-5;
            }
            return b;
        };
        store.appendBlocks(id, std::vector{block(0, 700), block(750, 500)});  // 50 lost
        store.markLostUntil(id, 1300);                                        // and 50 at the end
        store.addEvents(
            id, std::vector<core::storage::SessionEvent>{{0, "live", tactiscope::core::EventKind::Alarm, 0.7, 0.75, 0,
                                                          std::nullopt, std::nullopt, std::nullopt, "lost"}});
        store.addAnnotation(id, {0, 0.9, "Lin", "tare drift", "", ""});
        store.endSession(id, tactiscope::core::SessionStatus::Interrupted);
        store.decideVerdict(id, {0, tactiscope::core::VerdictRole::Automatic, tactiscope::core::Verdict::Pass, "",
                                 "2026-11-20T10:00:00.000Z", "", R"({"analysis":"live","defects":0,"sites":0})"});
        store.decideVerdict(id, {0, tactiscope::core::VerdictRole::Reviewer, tactiscope::core::Verdict::DefectsFound,
                                 "Q. Engineer", "2026-11-21T16:02:00.000Z", "crack at the root", ""});
    }
    const QString first = dir.filePath("first.csv"), second = dir.filePath("second.csv");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "csv", "--output", first}).exitCode, 0);
    const auto imported = runCli({"import", first, "--db", elsewhere});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.toStdString();
    EXPECT_TRUE(imported.out.contains("as session 1: 1200 rows of 2 channels at 1000 Hz, 100 missing"))
        << imported.out.toStdString();
    ASSERT_EQ(runCli({"sessions", "--db", elsewhere, "export", "1", "--format", "csv", "--output", second}).exitCode,
              0);
    EXPECT_EQ(readBytes(second), readBytes(first));
    // The metadata too: uuid, started and ended times, status, verdict, app
    // version, gaps, the records and their times.
    EXPECT_EQ(readBytes(dir.filePath("second.meta.json")), readBytes(dir.filePath("first.meta.json")));

    core::storage::SessionStore original(db.toStdString(), core::storage::Database::Access::ReadOnly);
    core::storage::SessionStore store(elsewhere.toStdString(), core::storage::Database::Access::ReadOnly);
    for (std::size_t c = 0; c < 2; ++c) {
        const auto before = original.readChannel(1, c, 0, 1300), copy = store.readChannel(1, c, 0, 1300);
        ASSERT_EQ(copy.size(), before.size());
        for (std::size_t i = 0; i < before.size(); ++i)
            ASSERT_EQ(std::bit_cast<std::uint64_t>(copy[i]), std::bit_cast<std::uint64_t>(before[i])) << c << ", " << i;
    }
    const auto copy = *store.session(1), recorded = *original.session(1);
    EXPECT_EQ(copy.uuid, recorded.uuid);
    EXPECT_EQ(copy.startedUtc, recorded.startedUtc);
    EXPECT_EQ(copy.status, tactiscope::core::SessionStatus::Interrupted);
    EXPECT_EQ(copy.verdict, tactiscope::core::Verdict::DefectsFound);
    const auto trail = store.verdicts(1), recordedTrail = original.verdicts(1);
    ASSERT_EQ(trail.size(), 2u);
    for (std::size_t d = 0; d < trail.size(); ++d) {
        EXPECT_EQ(trail[d].role, recordedTrail[d].role);
        EXPECT_EQ(trail[d].decidedBy, recordedTrail[d].decidedBy);
        EXPECT_EQ(trail[d].decidedUtc, recordedTrail[d].decidedUtc);
        EXPECT_EQ(trail[d].note, recordedTrail[d].note);
        EXPECT_EQ(trail[d].basisJson, recordedTrail[d].basisJson);
    }
    EXPECT_EQ(copy.metadata.operatorName, "Lin");
    EXPECT_EQ(store.channels(1)[0].descriptor, (core::ChannelDescriptor{"c", "pF", core::ChannelKind::Capacitance}));

    // The session is already in its own store and now in the other one.
    for (const QString& into : {db, elsewhere}) {
        const auto again = runCli({"import", first, "--db", into});
        EXPECT_EQ(again.exitCode, 2);
        EXPECT_TRUE(again.err.contains("is session " + QString::fromStdString(recorded.uuid) +
                                       ", already in this store as session 1; it was not imported again"))
            << again.err.toStdString();
    }
    EXPECT_EQ(core::storage::SessionStore(db.toStdString()).sessions().size(), 1u);
}

TEST(ImportCli, TimesSinceMidnightGiveTheRoundRateTheyWereWrittenAt)
{
    // 10 s at 500 Hz stamped in seconds since midnight, to the millisecond:
    // each step read back is 0.002 only to ±1.5e-11 s, so the median step
    // made the rate 500.000001717 Hz. The span over its 4999 steps does not.
    QTemporaryDir dir;
    const QString csv = dir.filePath("midnight.csv"), db = dir.filePath("s.tactiscope");
    QString text = QStringLiteral("time_s,a\n");
    for (int i = 0; i < 5000; ++i) text += QString::asprintf("%.3f,%d\n", 80000.0 + i * 0.002, i % 7);
    writeText(csv, text);
    const auto result = runCli({"import", csv, "--db", db});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_TRUE(result.out.contains("5000 rows of 1 channel at 500 Hz, 0 missing")) << result.out.toStdString();
    EXPECT_EQ(core::storage::SessionStore(db.toStdString()).session(1)->sampleRate_hz, 500.0);
}

TEST(ImportCli, AnImportKilledMidwayLeavesNothing)
{
    // Before, the part imported so far stayed, and read as an interrupted
    // recording. The import is one transaction now.
    QTemporaryDir dir;
    const QString csv = dir.filePath("long.csv"), db = dir.filePath("s.tactiscope");
    {
        QFile file(csv);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        QByteArray rows = "a,b\n";
        for (int i = 0; i < 2'000'000; ++i) {
            rows += QByteArray::number(i % 1000) + ",0.5\n";
            if (rows.size() > (1 << 20)) file.write(std::exchange(rows, QByteArray()));
        }
        file.write(rows);
    }
    QProcess importing;
    importing.start(QStringLiteral(TACTISCOPE_CLI), {"import", csv, "--db", db, "--rate", "1000"});
    ASSERT_TRUE(importing.waitForStarted());
    // Killed once it has written a good part of the session (the WAL holds
    // the pages the transaction could not keep in memory).
    const QString wal = db + "-wal";
    while (QFileInfo(wal).size() < 4 << 20 && !importing.waitForFinished(5)) {
    }
    ASSERT_EQ(importing.state(), QProcess::Running) << "the import ended before it could be killed midway";
    ::kill(static_cast<pid_t>(importing.processId()), SIGKILL);
    importing.waitForFinished();

    core::storage::SessionStore store(db.toStdString());
    EXPECT_TRUE(store.sessions().empty());
}

TEST(ImportCli, BadInputIsExitCodeTwoWithOneClearLineAndNothingStored)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const QString noTime = dir.filePath("no-time.csv"), jitter = dir.filePath("jitter.csv"),
                  text = dir.filePath("text.csv"), ragged = dir.filePath("ragged.csv"),
                  beyondFloat = dir.filePath("beyond-float.csv");
    writeText(noTime, "a,b\n1,2\n3,4\n");
    writeText(beyondFloat, "t,a\n0,1e308\n0.01,2\n");  // a double, but a stored sample would be inf
    writeText(jitter, "t,a\n0,1\n0.01,2\n0.02,3\n0.0335,4\n0.04,5\n");
    writeText(text, "t,a\n0,1\n0.01,one\n");
    writeText(ragged, "t,a\n0,1\n0.01\n");
    const struct {
        QStringList arguments;
        const char* message;
    } cases[] = {
        {{"import", dir.filePath("missing.csv"), "--db", db}, "cannot open"},
        {{"import", noTime, "--db", db}, "has no time column"},
        {{"import", jitter, "--db", db}, "line 5: t = 0.033500 s is off the"},
        {{"import", text, "--db", db}, "line 3, column 'a': 'one' is not a number"},
        {{"import", ragged, "--db", db}, "line 3 has 1 fields, the header has 2"},
        {{"import", beyondFloat, "--db", db},
         "line 2, column 'a': '1e308' is beyond the ±3.4e38 a stored sample holds"},
        {{"import", noTime, "--db", db, "--rate", "-5"},
         "--rate must be a number from 0.000001 to 1000000000 Hz, not '-5'"},
        {{"import", noTime, "--db", db, "--rate", "10", "--mode", "surgery"}, "--mode must be"},
        {{"import", noTime, "--db", db, "--rate", "10", "--time-column", "x"}, "has no column 'x'"},
        {{"import", noTime, "--rate", "10"}, "--db FILE is required"},
        {{"import", noTime, "--db", noTime, "--rate", "10"}, "is not a Tactiscope session store"},
    };
    for (const auto& c : cases) {
        const auto result = runCli(c.arguments);
        EXPECT_EQ(result.exitCode, 2) << c.arguments.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(QString::fromUtf8(c.message))) << result.err.toStdString();
        EXPECT_TRUE(result.err.startsWith(QStringLiteral("tactiscope-cli: "))) << result.err.toStdString();
    }
    // The fixed-rate import of the file without times works, and is the only session.
    ASSERT_EQ(runCli({"import", noTime, "--db", db, "--rate", "10"}).exitCode, 0);
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.sessions().size(), 1u);
}

TEST(AnalyzeCli, FindsTheEventsDetectFindsInTheSameRecording)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("scan.csv"), db = dir.filePath("s.tactiscope");
    ASSERT_EQ(runCli({"simulate", "--seconds", "8", "--seed", "3", "--output", csv}).exitCode, 0);
    ASSERT_EQ(runCli({"import", csv, "--db", db, "--subject", "door-5"}).exitCode, 0);
    const auto detect = runCli({"detect", csv, "--json", "--threshold", "0.8"});
    const auto analyze = runCli({"analyze", "--db", db, "--session", "last", "--json", "--threshold", "0.8"});
    ASSERT_EQ(analyze.exitCode, 0) << analyze.err.toStdString();
    const QJsonArray expected = json(detect.out)["events"].toArray(), found = json(analyze.out)["events"].toArray();
    ASSERT_GT(expected.size(), 3);
    ASSERT_EQ(found.size(), expected.size());
    for (qsizetype e = 0; e < expected.size(); ++e) {
        const QJsonObject want = expected[e].toObject(), got = found[e].toObject();
        EXPECT_EQ(got["direction"].toInt(), want["direction"].toInt()) << e;
        EXPECT_NEAR(got["start_s"].toDouble(), want["start_s"].toDouble(), 1e-9) << e;
        EXPECT_NEAR(got["end_s"].toDouble(), want["end_s"].toDouble(), 1e-9) << e;
        EXPECT_EQ(got["lag_ms"].toDouble(), want["lag_ms"].toDouble()) << e;
        // The store keeps binary32 samples: R moves in the 7th digit at most.
        EXPECT_NEAR(got["peak_r"].toDouble(), want["peak_r"].toDouble(), 1e-6) << e;
    }

    // Saved as a re-analysis beside the (empty) live events.
    const auto saved = runCli({"analyze", "--db", db, "--session", "1", "--threshold", "0.8", "--save", "t0.8"});
    ASSERT_EQ(saved.exitCode, 0) << saved.err.toStdString();
    EXPECT_TRUE(saved.out.contains(QStringLiteral("%1 events").arg(expected.size()))) << saved.out.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_TRUE(store.events(1).empty());
    EXPECT_EQ(store.events(1, "t0.8").size(), static_cast<std::size_t>(expected.size()));
}

TEST(AnalyzeCli, BadInputIsExitCodeTwo)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope"), csv = dir.filePath("f.csv");
    writeText(csv, "t,f [N]\n0,1\n0.01,2\n0.02,3\n");
    ASSERT_EQ(runCli({"import", csv, "--db", db, "--mode", "palpation"}).exitCode, 0);
    const struct {
        QStringList arguments;
        const char* message;
    } cases[] = {
        {{"analyze", "--db", db}, "--session ID|UUID|last is required"},
        {{"analyze", "--session", "last"}, "--db FILE is required"},
        {{"analyze", "--db", db, "--session", "7"}, "no session '7'"},
        {{"analyze", "--db", db, "--session", "last"}, "is a palpation session"},
        {{"analyze", "--db", db, "--session", "1", "--threshold", "high"}, "--threshold must be a number"},
        {{"analyze", "--db", db, "--session", "1", "--save", "live"}, "--save needs a name other than 'live'"},
        {{"analyze", "--db", csv, "--session", "1"}, "is not a Tactiscope session store"},
    };
    for (const auto& c : cases) {
        const auto result = runCli(c.arguments);
        EXPECT_EQ(result.exitCode, 2) << c.arguments.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(QString::fromUtf8(c.message))) << result.err.toStdString();
    }
}

// What `import` stores goes to the central store: before, a Latin-1 header
// (µ as the byte 0xB5) imported and then blocked every sync ("invalid byte
// sequence for encoding UTF8"), any text was accepted as a uuid, and a NUL
// in a subject was cut off on the server. Now the header is read as
// Latin-1 with a note; a uuid that is not one and a NUL are refused (exit
// 2) and nothing is stored.
TEST(ImportCli, WhatItStoresIsValidTextEverywhere)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const QString latin1 = dir.filePath("latin1.csv");
    {
        QFile file(latin1);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("t [s],a [\xB5V],b [\xB5V]\n0,1,2\n0.01,3,4\n0.02,5,6\n");
    }
    const auto imported = runCli({"import", latin1, "--db", db});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.toStdString();
    EXPECT_TRUE(imported.out.contains(QStringLiteral("note: the header is not UTF-8"))) << imported.out.toStdString();
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto channels = store.channels(store.sessions().front().id);
        ASSERT_EQ(channels.size(), 2u);
        EXPECT_EQ(channels[0].descriptor.unit, "µV");
    }

    // An export's side file naming a uuid that is not one, or a subject
    // with a NUL in it.
    const QString csv = dir.filePath("x.csv");
    writeText(csv, "t [s],a [N]\n0,1\n0.01,2\n");
    const QString other = dir.filePath("other.tactiscope");
    for (const char* session :
         {R"({"uuid": "x\"y\\z", "subject": "door"})", R"({"uuid": "", "subject": "door\u0000 17"})"}) {
        writeText(dir.filePath("x.meta.json"),
                  QStringLiteral(R"({"session": %1, "channels": [{"column": "a [N]", "name": "a", "unit": "N",
                                   "kind": "force"}]})")
                      .arg(QString::fromUtf8(session)));
        const auto refused = runCli({"import", csv, "--db", other});
        EXPECT_EQ(refused.exitCode, 2) << session << ": " << refused.err.toStdString();
        EXPECT_TRUE(refused.err.contains(QStringLiteral("is not a uuid")) ||
                    refused.err.contains(QStringLiteral("a NUL character")))
            << refused.err.toStdString();
    }
    if (QFile::exists(other)) {
        core::storage::SessionStore store(other.toStdString(), core::storage::Database::Access::ReadOnly);
        EXPECT_TRUE(store.sessions().empty());
    }
}
