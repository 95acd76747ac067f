// `tactiscope-cli record` against `tactiscope-cli emulate`, both as real
// processes over a real pseudo-terminal, into a real store: the samples in
// the store are exactly those the emulator sent, the mode's analysis runs on
// them (events of a panel scan, stiffness readings of palpation), Ctrl-C
// ends a recording cleanly, bad input is refused with exit code 2, and a
// store reached through a link is the same store.
#include "core/SampleBlock.h"
#include "core/storage/Recorder.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <thread>

using namespace tactiscope;
using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;

using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

TEST(RecordCli, TheStoreHoldsExactlyTheSamplesTheEmulatorSent)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("line3.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000", "--seed", "9"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "1.5", "--db", db, "--subject", "door-17",
                                "--operator", "Ada", "--mode", "panel-scan"});
    stopEmulator(emulator);
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_TRUE(result.out.endsWith(QStringLiteral("\n")));
    EXPECT_EQ(result.out.count(QLatin1Char('\n')), 1) << result.out.toStdString();  // one line
    EXPECT_TRUE(result.out.contains(QStringLiteral(" 0 lost, 0 CRC errors"))) << result.out.toStdString();
    const std::int64_t id = sessionIdIn(result.out);
    ASSERT_GT(id, 0) << result.out.toStdString();

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = store.session(id);
    ASSERT_TRUE(session.has_value());
    EXPECT_EQ(session->status, tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(session->metadata.mode, tactiscope::core::Mode::PanelScan);
    EXPECT_EQ(session->metadata.subject, "door-17");
    EXPECT_EQ(session->metadata.operatorName, "Ada");
    EXPECT_EQ(session->metadata.deviceSerial, "EMU-9");
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_DOUBLE_EQ(channels[0].sampleRate_hz, 1000.0);
    EXPECT_TRUE(store.gaps(id).empty());

    // 1.5 s at 1000 Hz, exactly.
    const std::uint64_t n = store.sampleCount(id);
    EXPECT_EQ(n, 1500u);
    EXPECT_DOUBLE_EQ(session->duration_s(), 1.5);
    EXPECT_NE(result.out.indexOf(QStringLiteral(": %1 samples per channel").arg(n)), -1);
    // The emulator's samples are the scenario's, sent as binary32.
    auto scenario = devices::simulator::makeScenario("panel-scan", 9, 1000.0);
    core::SampleBlock expected(2, n, 0.0, 0.001);
    scenario->generate(expected);
    for (std::size_t c = 0; c < 2; ++c) {
        const auto stored = store.readChannel(id, c, 0, n);
        ASSERT_EQ(stored.size(), n);
        for (std::uint64_t i = 0; i < n; ++i)
            ASSERT_EQ(stored[i], static_cast<double>(static_cast<float>(expected.value(c, i)))) << c << ", " << i;
    }
}

TEST(RecordCli, APanelScanRecordingStoresTheDetectorsEventsAndTheReportListsThem)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("line3.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "500", "--seed", "5"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "8", "--db", db, "--subject", "door-8"});
    stopEmulator(emulator);
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();

    // The scenario's stroke is x(t) = 0.1·sin(πt) m with one dent at 30 mm
    // and B 15 mm behind A: each 2 s stroke crosses the dent once each way,
    // and B meets it (asin 0.45 − asin 0.30)/π = 51.5 ms after A (the
    // panel-scan test's figure), in both directions.
    const auto show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject json = QJsonDocument::fromJson(show.out.toUtf8()).object();
    EXPECT_EQ(json["session"].toObject()["mode"].toString(), "panel-scan");
    EXPECT_EQ(json["session"].toObject()["verdict"].toString(), "defects found");
    const QJsonArray events = json["events"].toArray();
    EXPECT_GE(events.size(), 7) << show.out.toStdString();  // 8 crossings, one maybe cut by the ends
    EXPECT_LE(events.size(), 9);
    const double crossing_s = (std::asin(0.45) - std::asin(0.30)) / std::numbers::pi;
    int forwards = 0, backwards = 0;
    for (const auto& value : events) {
        const QJsonObject event = value.toObject();
        EXPECT_EQ(event["kind"].toString(), "defect");
        EXPECT_NEAR(event["lag_s"].toDouble(), crossing_s, 0.004) << event["start_s"].toDouble();
        (event["direction"].toInt() > 0 ? forwards : backwards) += 1;
    }
    EXPECT_LE(std::abs(forwards - backwards), 1);
    EXPECT_TRUE(result.out.contains(QStringLiteral("panel-scan: %1 defects stored").arg(events.size())))
        << result.out.toStdString();

    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    const QString pdf = dir.filePath("door-8.pdf");
    const auto report = runCli({"report", "--db", db, "--session", "last", "--output", pdf});
    ASSERT_EQ(report.exitCode, 0) << report.err.toStdString();
    const QString text = pdfText(pdf);
    // Every crossing of the one dent is one site, which the verdict counts.
    EXPECT_TRUE(result.out.contains(QStringLiteral("defects stored at 1 site, verdict defects found")))
        << result.out.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Defect sites (1)"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Crossings (%1)").arg(events.size()))) << text.toStdString();
    EXPECT_TRUE(text.simplified().contains(
        QStringLiteral("automatic: defects found (live detector: %1 defects at 1 site").arg(events.size())))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("A then B"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("B then A"))) << text.toStdString();
}

TEST(RecordCli, APalpationRecordingStoresAStiffnessReadingPerPress)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("clinic.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "palpation", "--seed", "3"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "12", "--db", db, "--site", "B2"});
    stopEmulator(emulator);
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = store.sessions().front();
    EXPECT_EQ(session.metadata.mode, tactiscope::core::Mode::Palpation);
    const auto readings = store.readings(session.id);
    // A press, hold and release take about 2–3 s with a 1 s pause between
    // presses: 12 s hold at least three whole ones.
    ASSERT_GE(readings.size(), 3u) << result.out.toStdString();
    for (const auto& reading : readings) {
        EXPECT_EQ(reading.kind, tactiscope::core::ReadingKind::Compliance);
        EXPECT_EQ(reading.unit, "N/m");
        EXPECT_NEAR(reading.value, 117.0, 0.05 * 117.0);  // the scenario's specimen
        EXPECT_EQ(reading.site, "B2");
        EXPECT_LT(reading.start_s, reading.end_s);
    }
    EXPECT_TRUE(result.out.contains(QStringLiteral("palpation: %1 stiffness readings stored").arg(readings.size())))
        << result.out.toStdString();
}

TEST(RecordCli, AModeTheDeviceCannotFeedIsRefusedWithTheChannelsItNeeds)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("s.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "2", "--db", db, "--mode", "palpation"});
    stopEmulator(emulator);
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(result.err.contains(QStringLiteral("cannot record in this mode: "))) << result.err.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("displacement"))) << result.err.toStdString();
    EXPECT_TRUE(result.out.isEmpty()) << result.out.toStdString();
    // Nothing was recorded.
    if (std::filesystem::exists(db.toStdString())) {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        EXPECT_TRUE(store.sessions().empty());
    }
}

// Ctrl+C, `kill`, and a closed terminal (SIGHUP, which before killed the
// recording without a clean end) each end it cleanly.
class RecordCliStopSignal : public ::testing::TestWithParam<int> {};

TEST_P(RecordCliStopSignal, EndsTheRecordingAndKeepsTheData)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("s.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "palpation", "--rate", "500"}));
    QProcess record;
    record.start(QStringLiteral(TACTISCOPE_CLI), {"record", "--port", link, "--db", db, "--mode", "palpation"});
    ASSERT_TRUE(record.waitForStarted());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    ::kill(static_cast<pid_t>(record.processId()), GetParam());
    ASSERT_TRUE(record.waitForFinished(10000));
    stopEmulator(emulator);
    EXPECT_EQ(record.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(record.exitCode(), 0) << record.readAllStandardError().toStdString();
    const QString out = QString::fromUtf8(record.readAllStandardOutput());
    const std::int64_t id = sessionIdIn(out);
    ASSERT_GT(id, 0) << out.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.session(id)->status, tactiscope::core::SessionStatus::Complete);
    EXPECT_GT(store.sampleCount(id), 100u);
    EXPECT_EQ(store.channels(id).size(), 3u);
}

INSTANTIATE_TEST_SUITE_P(RecordCli, RecordCliStopSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const ::testing::TestParamInfo<int>& signal) {
                             return std::string(signal.param == SIGINT    ? "SIGINT"
                                                : signal.param == SIGTERM ? "SIGTERM"
                                                                          : "SIGHUP");
                         });

TEST(RecordCli, AKilledRecordingKeepsItsCommittedSamplesAndIsMarkedInterrupted)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("s.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000", "--seed", "4"}));
    QProcess record;
    record.start(QStringLiteral(TACTISCOPE_CLI), {"record", "--port", link, "--db", db});
    ASSERT_TRUE(record.waitForStarted());
    std::this_thread::sleep_for(std::chrono::milliseconds(2000));
    ::kill(static_cast<pid_t>(record.processId()), SIGKILL);  // no chance to clean up
    ASSERT_TRUE(record.waitForFinished(5000));
    stopEmulator(emulator);

    core::storage::SessionStore store(db.toStdString());  // read-write: recovers
    ASSERT_EQ(store.sessions().size(), 1u);
    const auto session = store.sessions().front();
    EXPECT_EQ(session.status, tactiscope::core::SessionStatus::Interrupted);
    EXPECT_EQ(store.checkIntegrity(), "ok");
    // Commits come every 250 ms, so about 2 s of recording left more than
    // half a second of samples, all of them the emulator's, in order.
    const std::uint64_t n = store.sampleCount(session.id);
    EXPECT_GT(n, 500u);
    EXPECT_TRUE(store.gaps(session.id).empty());
    auto scenario = devices::simulator::makeScenario("panel-scan", 4, 1000.0);
    core::SampleBlock expected(2, n, 0.0, 0.001);
    scenario->generate(expected);
    const auto stored = store.readChannel(session.id, 0, 0, n);
    for (std::uint64_t i = 0; i < n; ++i)
        ASSERT_EQ(stored[i], static_cast<double>(static_cast<float>(expected.value(0, i)))) << i;
}

TEST(RecordCli, BadInputExitsWithCodeTwoAndAMissingPortWithOne)
{
    QTemporaryDir dir;
    const QString notes = dir.filePath("notes.txt");
    std::ofstream(notes.toStdString()) << "not a store\n";
    QProcess emulator;
    const QString link = dir.filePath("probe");
    ASSERT_TRUE(startEmulator(emulator, link));
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"record", "--db", "x"}, "--port PATH is required"},
        {{"record", "--port", "/dev/ttyX"}, "--db FILE is required"},
        {{"record", "--port", "/dev/ttyX", "--db", "x", "--mode", "sculpture"}, "--mode must be"},
        {{"record", "--port", "/dev/ttyX", "--db", "x", "--seconds", "-1"},
         "--seconds must be a number from 0.001 to 2678400 s"},
        {{"record", "--port", "/dev/ttyX", "--db", "x", "--baud", "fast"}, "--baud must be"},
        {{"record", "--port", link, "--db", notes, "--seconds", "1"}, "is not a Tactiscope session store"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto result = runCli(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(message)) << result.err.toStdString();
    }
    {
        // A store another recorder is writing into.
        const QString busy = dir.filePath("busy.tactiscope");
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::Palpation;
        core::storage::Recorder other(busy.toStdString(), metadata, {{"x", "m", core::ChannelKind::Position}}, 100.0,
                                      1000);
        const auto result = runCli({"record", "--port", link, "--db", busy, "--seconds", "1"});
        EXPECT_EQ(result.exitCode, 2);
        EXPECT_TRUE(result.err.contains(QStringLiteral("another Tactiscope is recording into")))
            << result.err.toStdString();
    }
    stopEmulator(emulator);
    const auto missing =
        runCli({"record", "--port", dir.filePath("no-such-port"), "--db", dir.filePath("s.tactiscope")});
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_TRUE(missing.err.contains(QStringLiteral("no-such-port"))) << missing.err.toStdString();
}

// A store is its file, whatever name reaches it (issue 54). Through a
// symbolic link a second recorder is refused and a reader sees the
// session being recorded as recording (a sync sends it only once
// complete); before, each name had its own lock, so both recorded and a
// reader through the link took the live session for one cut by a crash.
// A store with two names (a hard link) would be two write-ahead logs of
// one file: refused, saying why, by every command.
TEST(RecordCli, AStoreIsOneFileWhateverNameReachesIt)
{
    QTemporaryDir dir;
    const QString real = dir.filePath("line3.tactiscope");
    const QString link = dir.filePath("link.tactiscope");
    core::storage::SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::General;
    auto recorder = std::make_unique<core::storage::Recorder>(
        real.toStdString(), metadata, std::vector<core::ChannelDescriptor>{{"x", "m", core::ChannelKind::Position}},
        100.0, 1000);
    std::filesystem::create_symlink(real.toStdString(), link.toStdString());
    QProcess emulator;
    const QString probe = dir.filePath("probe");
    ASSERT_TRUE(startEmulator(emulator, probe));
    const auto second = runCli({"record", "--port", probe, "--db", link, "--seconds", "1"});
    stopEmulator(emulator);
    EXPECT_EQ(second.exitCode, 2) << second.out.toStdString();
    EXPECT_TRUE(second.err.contains(QStringLiteral("another Tactiscope is recording into")))
        << second.err.toStdString();
    const auto shown = runCli({"sessions", "show", "last", "--db", link});
    EXPECT_EQ(shown.exitCode, 0) << shown.err.toStdString();
    EXPECT_TRUE(shown.out.contains(QRegularExpression(QStringLiteral("status +recording\n"))))
        << shown.out.toStdString();
    recorder->finish(tactiscope::core::SessionStatus::Complete);
    recorder.reset();
    // No lock or log of its own beside the link.
    EXPECT_FALSE(std::filesystem::exists(link.toStdString() + "-recorder.lock"));
    EXPECT_FALSE(std::filesystem::exists(link.toStdString() + "-wal"));

    const QString hard = dir.filePath("hard.tactiscope");
    std::filesystem::create_hard_link(real.toStdString(), hard.toStdString());
    for (const QString& name : {real, hard}) {
        const auto listed = runCli({"sessions", "list", "--db", name});
        EXPECT_EQ(listed.exitCode, 2) << name.toStdString();
        EXPECT_TRUE(listed.err.contains(QStringLiteral("has 2 names (hard links)"))) << listed.err.toStdString();
    }
}

// The host's clock set back a day one second into a recording (a shim in
// the recorder's process; the machine's clock is not touched): the session
// ends after it began, dated by how long it lasted, and says why (issue
// 54). Before, it was stored as ending a day before its start.
TEST(RecordCli, AClockSetBackWhileRecordingNeverEndsASessionBeforeItsStart)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("line3.tactiscope");
    QProcess emulator;
    const QString probe = dir.filePath("probe");
    ASSERT_TRUE(startEmulator(emulator, probe));
    auto environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("LD_PRELOAD"), QStringLiteral(TACTISCOPE_CLOCK_STEP_PRELOAD));
    environment.insert(QStringLiteral("TACTISCOPE_TEST_CLOCK_STEP"), QStringLiteral("1,-86400"));
    const auto result = runCli({"record", "--port", probe, "--db", db, "--seconds", "3"}, environment);
    stopEmulator(emulator);
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = store.session(sessionIdIn(result.out));
    ASSERT_TRUE(session);
    // About the 3 s of samples (the recorder is made around the stream's start).
    const auto utc = [](const std::string& text) {
        return QDateTime::fromString(QString::fromStdString(text), Qt::ISODateWithMs);
    };
    const qint64 lasted_ms = utc(session->startedUtc).msecsTo(utc(session->endedUtc));
    EXPECT_GE(lasted_ms, 2500) << session->startedUtc << " to " << session->endedUtc;
    EXPECT_LT(lasted_ms, 6000) << session->startedUtc << " to " << session->endedUtc;
    const auto events = store.events(session->id);
    EXPECT_TRUE(std::ranges::any_of(events, [](const auto& e) {
        return e.note.starts_with("the host's clock was set back by 8640") &&
               e.note.ends_with("its end is dated by its start and how long it lasted");
    })) << events.size();
}
