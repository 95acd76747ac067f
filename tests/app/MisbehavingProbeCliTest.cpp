// `tactiscope-cli record` from a probe whose firmware misbehaves, emulated
// behind a real pty (`emulate --fault`), into a real store: what a device
// says about its sequence and its clock is checked, never believed alone.
// A restart is a gap of the time the host saw pass plus an alarm, not the
// hours a wrapped sequence would claim; a sequence that never moves or
// jumps once loses nothing. Before, the 6 s restart recording was stored as
// 658 s with 652 360 invented lost samples (issue 19).
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"

#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>

using namespace tactiscope;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

struct Recorded {
    tactiscope::testing::CliResult result;
    std::int64_t session = -1;
};

// Records `seconds` from a 1 kHz panel-scan probe with `fault`.
Recorded recordFrom(const QTemporaryDir& dir, const QString& fault, const QString& seconds)
{
    const QString link = dir.filePath("probe");
    QProcess emulator;
    if (!startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000", "--fault", fault})) return {};
    Recorded recorded;
    recorded.result = runCli(
        {"record", "--port", link, "--seconds", seconds, "--db", dir.filePath("s.tactiscope"), "--subject", "door-3"});
    stopEmulator(emulator);
    recorded.session = sessionIdIn(recorded.result.out);
    return recorded;
}

// The store the recordings went into, read-only.
core::storage::SessionStore storeIn(const QTemporaryDir& dir)
{
    return core::storage::SessionStore(dir.filePath("s.tactiscope").toStdString(),
                                       core::storage::Database::Access::ReadOnly);
}

std::vector<core::storage::SessionEvent> alarms(core::storage::SessionStore& store, std::int64_t session)
{
    auto events = store.events(session);
    std::erase_if(events, [](const auto& e) { return e.kind != core::EventKind::Alarm; });
    return events;
}

}  // namespace

TEST(MisbehavingProbe, ARestartIsAGapOfTheTimeItWasAwayAndAnAlarm)
{
    QTemporaryDir dir;
    // The emulator falls silent for 0.5 s at 1.5 s of its stream, then its
    // sequence and clock begin again at 0.
    const auto recorded = recordFrom(dir, "restart@1.5", "4");
    ASSERT_EQ(recorded.result.exitCode, 0) << recorded.result.err.toStdString();
    ASSERT_GT(recorded.session, 0) << recorded.result.out.toStdString();
    EXPECT_TRUE(recorded.result.err.contains(QStringLiteral("restarted"))) << recorded.result.err.toStdString();

    auto store = storeIn(dir);
    // 4 s of recording at 1 kHz, the restart's half second included: not 658 s.
    const auto n = store.sampleCount(recorded.session);
    EXPECT_GE(n, 3000u);
    EXPECT_LE(n, 4600u);
    const auto gaps = store.gaps(recorded.session);
    ASSERT_EQ(gaps.size(), 1u);
    // The half second the probe was away, give or take the pty's delivery.
    EXPECT_NEAR(static_cast<double>(gaps[0].count), 500.0, 150.0);
    const auto restart = alarms(store, recorded.session);
    ASSERT_EQ(restart.size(), 1u);
    EXPECT_NE(restart[0].note.find("restarted"), std::string::npos) << restart[0].note;
    EXPECT_NEAR(restart[0].start_s, static_cast<double>(gaps[0].firstIndex) / 1000.0, 0.05);
}

TEST(MisbehavingProbe, ASequenceThatNeverMovesLosesNothing)
{
    QTemporaryDir dir;
    const auto recorded = recordFrom(dir, "frozen-sequence", "2");
    ASSERT_EQ(recorded.result.exitCode, 0) << recorded.result.err.toStdString();
    ASSERT_GT(recorded.session, 0) << recorded.result.out.toStdString();
    EXPECT_TRUE(recorded.result.out.contains(QStringLiteral(" 0 lost,"))) << recorded.result.out.toStdString();

    auto store = storeIn(dir);
    // Every frame's sequence is 0: 65 535 frames "lost" each time, before.
    EXPECT_LE(store.sampleCount(recorded.session), 2600u);
    EXPECT_TRUE(store.gaps(recorded.session).empty());
    // Told once, in the record: the device's sequence is not to be trusted.
    const auto told = alarms(store, recorded.session);
    ASSERT_EQ(told.size(), 1u);
    EXPECT_NE(told[0].note.find("sequence number"), std::string::npos) << told[0].note;
}

TEST(MisbehavingProbe, OneFramesSequenceJumpLosesNothing)
{
    QTemporaryDir dir;
    const auto recorded = recordFrom(dir, "sequence-jump@1", "2.5");
    ASSERT_EQ(recorded.result.exitCode, 0) << recorded.result.err.toStdString();
    ASSERT_GT(recorded.session, 0) << recorded.result.out.toStdString();
    EXPECT_TRUE(recorded.result.out.contains(QStringLiteral(" 0 lost,"))) << recorded.result.out.toStdString();

    auto store = storeIn(dir);
    EXPECT_LE(store.sampleCount(recorded.session), 3100u);  // 2.5 s, not 661 s
    EXPECT_TRUE(store.gaps(recorded.session).empty());
    EXPECT_EQ(alarms(store, recorded.session).size(), 1u);
}

TEST(MisbehavingProbe, AFaultTheEmulatorCannotSpeakIsRefused)
{
    QTemporaryDir dir;
    const auto result = runCli({"emulate", "--link", dir.filePath("probe"), "--fault", "restart"});
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(result.err.contains(QStringLiteral("--fault"))) << result.err.toStdString();
    const auto text =
        runCli({"emulate", "--link", dir.filePath("probe"), "--protocol", "text", "--fault", "frozen-sequence"});
    EXPECT_EQ(text.exitCode, 2);
    EXPECT_TRUE(text.err.contains(QStringLiteral("TSP/1"))) << text.err.toStdString();
}

TEST(MisbehavingProbe, ARateTheDeviceLiesAboutIsRefusedBeforeAnythingIsRecorded)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    QProcess emulator;
    // INFO says 1 mHz; the probe streams 1 kHz. Before, 0 of 6000 samples
    // were stored ("6000 lost") and the command exited 0.
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000", "--info-rate", "0.001"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "3", "--db", dir.filePath("s.tactiscope")});
    stopEmulator(emulator);
    EXPECT_EQ(result.exitCode, 1) << result.out.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("says it samples at 0.001 Hz"))) << result.err.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("1000 Hz"))) << result.err.toStdString();
    if (QFileInfo::exists(dir.filePath("s.tactiscope"))) {  // opened first, and nothing recorded into it
        core::storage::SessionStore store(dir.filePath("s.tactiscope").toStdString(),
                                          core::storage::Database::Access::ReadOnly);
        EXPECT_TRUE(store.sessions().empty());
    }
}

TEST(MisbehavingProbe, AProbeLostForGoodIsAGapToTheStopAnAlarmAndExitOne)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    QProcess emulator;
    // The probe streams 1.5 s, hangs up and never comes back; the recording
    // runs 4 s. Before: exit 0, "0 lost", no gap, the missing time nowhere.
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000", "--seconds", "1.5"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "4", "--db", dir.filePath("s.tactiscope")});
    stopEmulator(emulator);
    EXPECT_EQ(result.exitCode, 1) << result.out.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("the probe was lost at 1.")) &&
                result.err.contains(QStringLiteral("and did not come back;")) &&
                result.err.contains(QStringLiteral("samples kept")))
        << result.err.toStdString();
    const std::int64_t id = sessionIdIn(result.out);
    ASSERT_GT(id, 0) << result.out.toStdString();

    auto store = storeIn(dir);
    const auto session = store.session(id);
    ASSERT_TRUE(session);
    EXPECT_FALSE(session->verdict);  // a panel left half-inspected passes nothing
    const auto gaps = store.gaps(id);
    ASSERT_FALSE(gaps.empty());
    const auto& tail = gaps.back();
    EXPECT_EQ(tail.firstIndex + tail.count, store.sampleCount(id));  // open to the session's end
    EXPECT_GE(tail.count, 2000u);                                    // of the 4 s, 1.5 s were streamed
    EXPECT_NEAR(static_cast<double>(tail.firstIndex), 1500.0, 200.0);
    const auto lost = alarms(store, id);
    ASSERT_EQ(lost.size(), 1u);
    EXPECT_NE(lost[0].note.find("did not come back"), std::string::npos) << lost[0].note;
    EXPECT_NEAR(lost[0].start_s, static_cast<double>(tail.firstIndex) / 1000.0, 0.01);
    // The line's count is the store's, to the sample (it said 2035 where
    // the store held 2034).
    std::uint64_t storedLost = 0;
    for (const auto& gap : gaps) storedLost += gap.count;
    EXPECT_TRUE(result.out.contains(QStringLiteral(" samples per channel, %1 lost, ").arg(storedLost)))
        << result.out.toStdString() << " (the store holds " << storedLost << " lost)";
}

namespace {

// A 6 s recording of a 1 kHz panel-scan probe (seed 1) that hangs up after
// a second, replaced on the port by an emulator started with `second`.
struct Replugged {
    int exitCode = -1;
    QString out, err;
    std::int64_t session = 0;
};

Replugged recordAcrossAReplug(const QTemporaryDir& dir, const QStringList& second)
{
    const QString link = dir.filePath("probe");
    Replugged result;
    QProcess first;
    if (!startEmulator(first, link, {"--scenario", "panel-scan", "--rate", "1000", "--seconds", "1", "--seed", "1"}))
        return result;
    QProcess record;
    record.start(QStringLiteral(TACTISCOPE_CLI),
                 {"record", "--port", link, "--seconds", "6", "--db", dir.filePath("s.tactiscope")});
    if (!record.waitForStarted() || !first.waitForFinished(10000)) return result;  // hung up after its second
    QProcess other;
    if (!startEmulator(other, link, second)) return result;
    record.waitForFinished(20000);
    stopEmulator(other);
    result.exitCode = record.exitCode();
    result.out = QString::fromUtf8(record.readAllStandardOutput());
    result.err = QString::fromUtf8(record.readAllStandardError());
    result.session = sessionIdIn(result.out);
    return result;
}

// Samples stored, not in a gap.
std::uint64_t keptSamples(core::storage::SessionStore& store, std::int64_t session)
{
    std::uint64_t lost = 0;
    for (const auto& gap : store.gaps(session)) lost += gap.count;
    return store.sampleCount(session) - lost;
}

}  // namespace

// Back on the same port at another rate: another device, for the record.
TEST(MisbehavingProbe, AProbeThatComesBackChangedEndsTheRecordingWithWhatCameBefore)
{
    QTemporaryDir dir;
    const auto r = recordAcrossAReplug(dir, {"--scenario", "panel-scan", "--rate", "500"});
    EXPECT_EQ(r.exitCode, 1) << r.out.toStdString();
    // Said, and not contradicted ("did not come back" beside "came back").
    EXPECT_FALSE(r.err.contains(QStringLiteral("did not come back"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("came back at another rate (500 Hz, where it was 1000 Hz)")))
        << r.err.toStdString();
    ASSERT_GT(r.session, 0) << r.out.toStdString();
    auto store = storeIn(dir);
    EXPECT_DOUBLE_EQ(store.channels(r.session)[0].sampleRate_hz, 1000.0);  // nothing of the 500 Hz device mixed in
    EXPECT_NEAR(static_cast<double>(keptSamples(store, r.session)), 1000.0, 150.0);  // the first device's second
    const auto told = alarms(store, r.session);
    ASSERT_FALSE(told.empty());
    EXPECT_NE(told.front().note.find("another rate"), std::string::npos) << told.front().note;
}

// Another probe of the same kind (same channels and rate, another serial
// number: the emulator's is EMU-<seed>) on the port a second after the
// first leaves: before, "the probe was away 2.0 s and came back", both
// probes' samples in one session labelled with the first, exit 0. Now the
// recording ends with what the first one gave, an alarm names both, exit 1.
TEST(MisbehavingProbe, AnotherProbeOnThePortIsNotTakenForTheFirst)
{
    QTemporaryDir dir;
    const auto r = recordAcrossAReplug(dir, {"--scenario", "panel-scan", "--rate", "1000", "--seed", "2"});
    EXPECT_EQ(r.exitCode, 1) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("another device came back on the port"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("EMU-2, where"))) << r.err.toStdString();
    ASSERT_GT(r.session, 0) << r.out.toStdString();
    auto store = storeIn(dir);
    EXPECT_NEAR(static_cast<double>(keptSamples(store, r.session)), 1000.0, 150.0);  // the first probe's second only
    const auto told = alarms(store, r.session);
    ASSERT_FALSE(told.empty());
    EXPECT_NE(told.front().note.find("EMU-1"), std::string::npos) << told.front().note;
}

// A device sampling at 1200 Hz whose INFO and clock both say 1000 Hz: the
// arrival check only caught a factor of 2, so it was accepted and 6.11 s
// were stored as 7.23 s; then only two 5 s windows 20 % off ended it, so
// a 6 s panel was stored as 7.27 s with a verdict. The host's arrivals now
// end it within its first seconds, with the reason, exit 1.
TEST(MisbehavingProbe, ADeviceWhoseRateAndClockBothLieByTwentyPercentIsStopped)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(
        emulator, link, {"--scenario", "panel-scan", "--rate", "1200", "--info-rate", "1000", "--clock-rate", "1000"}));
    const auto result = runCli({"record", "--port", link, "--seconds", "6", "--db", dir.filePath("s.tactiscope")});
    stopEmulator(emulator);
    EXPECT_EQ(result.exitCode, 1) << result.out.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("arrive at about 1"))) << result.err.toStdString();
    EXPECT_TRUE(result.err.contains(QStringLiteral("not at the 1000 Hz it says"))) << result.err.toStdString();
}
